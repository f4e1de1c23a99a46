// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lines, tokens and numbers of a text mesh file held in memory, for the
// disk_uv tool's readers: every line is bounded, and every problem is
// reported as one line naming the file, the line and the token.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_TEXT_SCANNER_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_TEXT_SCANNER_H

#include <CGAL/Disk_segmentation/IO/File_error.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// A mesh file's lines are short (an OBJ polygon of 10^5 vertices takes
// about 1 MB); a longer one means a file without line breaks (a device, a
// binary file under a text extension), named before it is scanned further.
constexpr std::size_t max_line_bytes = std::size_t(1) << 20;


inline bool is_blank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// `bytes` as a count a user reads: "4 GiB", "1 MiB" or "1234 bytes".
inline std::string size_text(unsigned long long bytes)
{
  if(bytes != 0 && bytes % (1ull << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  if(bytes != 0 && bytes % (1ull << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// A token as it may appear in a one-line message: quoted, shortened, and
// with control and non-ASCII bytes escaped (a binary file's tokens).
inline std::string quote_token(std::string_view token)
{
  const std::size_t shown = 24;
  std::string text = "'";
  for(std::size_t i = 0; i < token.size() && i < shown; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if(c < 0x20 || c >= 0x7f)
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02x", c);
      text += escaped;
    }
    else
      text += char(c);
  }
  if(token.size() > shown)
    text += "...";
  return text + "'";
}

// Splits `line` at blanks; a `comment` character drops the rest of the line.
inline void split_tokens(std::string_view line, std::vector<std::string_view>& tokens, char comment = '#')
{
  tokens.clear();
  const std::size_t end = comment == '\0' ? line.size() : (std::min)(line.find(comment), line.size());
  // Each pass moves i past at least one byte (a blank or a token).
  std::size_t i = 0;
  while(i < end)
  {
    while(i < end && is_blank(line[i]))
      ++i;
    const std::size_t start = i;
    while(i < end && !is_blank(line[i]))
      ++i;
    if(i > start)
      tokens.push_back(line.substr(start, i - start));
  }
}

// A decimal number as strtod (strtof for a float) reads it, except that the
// whole token must be the number. 1e400 gives infinity (named by the callers
// as a non-finite coordinate) and 1e-400 zero, as a user would expect. A PLY
// `float` property is read as a float: it rounds once, to float.
template <typename Real>
bool parse_number(std::string_view token, Real& value)
{
  static_assert(std::is_same<Real, double>::value || std::is_same<Real, float>::value, "double or float");
  const char* first = token.data();
  if(!token.empty() && token[0] == '+')
    ++first;
  const auto result = std::from_chars(first, token.data() + token.size(), value);
  if(result.ptr != token.data() + token.size() || first == token.data() + token.size())
    return false;
  if(result.ec == std::errc::result_out_of_range)
  {
    const std::string text(token);
    if constexpr(std::is_same<Real, float>::value)
      value = std::strtof(text.c_str(), nullptr);
    else
      value = std::strtod(text.c_str(), nullptr);
  }
  return result.ec == std::errc() || result.ec == std::errc::result_out_of_range;
}

// A non-negative decimal integer, the whole token.
inline bool parse_index(std::string_view token, std::size_t& value)
{
  unsigned long long v = 0;
  const auto result = std::from_chars(token.data(), token.data() + token.size(), v);
  value = static_cast<std::size_t>(v);
  return result.ec == std::errc() && result.ptr == token.data() + token.size() && !token.empty();
}

// A decimal integer with an optional sign, the whole token. `overflow` is
// set for a well-formed integer that does not fit.
inline bool parse_integer(std::string_view token, long long& value, bool& overflow)
{
  std::string_view digits = token;
  if(!digits.empty() && digits[0] == '+')
    digits.remove_prefix(1);
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  overflow = result.ec == std::errc::result_out_of_range && result.ptr == digits.data() + digits.size();
  return result.ec == std::errc() && result.ptr == digits.data() + digits.size() && !digits.empty();
}


// Walks a text file held in memory line by line, or token by token across
// lines, and throws the file's File_error naming the current line.
class Text_scanner
{
public:
  // `text` starts at line `first_line` of the file `name` of format `ext`.
  Text_scanner(std::string_view text, const std::string& name, const char* ext, std::size_t first_line = 1)
    : text_(text), name_(name), ext_(ext), line_number_(first_line - 1)
  {}

  // Moves to the next line (without its line break); false at the end.
  bool next_line()
  {
    if(position_ >= text_.size())
    {
      line_ = rest_ = std::string_view();
      return false;
    }
    ++line_number_;
    const std::size_t searched = (std::min)(text_.size() - position_, max_line_bytes + 1);
    const void* found = std::memchr(text_.data() + position_, '\n', searched);
    const std::size_t length =
      found ? std::size_t(static_cast<const char*>(found) - (text_.data() + position_)) : searched;
    if(length > max_line_bytes)
      fail("longer than " + size_text(max_line_bytes) + " without a line break (not a text file?)");
    line_ = rest_ = text_.substr(position_, length);
    position_ += length + (found ? 1 : 0);
    return true;
  }

  // Moves to the next line that has a token, splits into `tokens`; false
  // at the end of the text.
  bool next_tokens(std::vector<std::string_view>& tokens, char comment = '#')
  {
    // Each pass takes a line (next_line moves past at least one byte).
    while(next_line())
    {
      split_tokens(line_, tokens, comment);
      if(!tokens.empty())
        return true;
    }
    return false;
  }

  // The next token, across line breaks; false at the end of the text.
  bool next_token(std::string_view& token)
  {
    // Each pass returns a token or takes a line: at most the lines left + 1.
    for(;;)
    {
      std::size_t i = 0;
      while(i < rest_.size() && is_blank(rest_[i]))
        ++i;
      if(i < rest_.size())
      {
        std::size_t end = i;
        while(end < rest_.size() && !is_blank(rest_[end]))
          ++end;
        token = rest_.substr(i, end - i);
        rest_.remove_prefix(end);
        return true;
      }
      if(!next_line())
        return false;
    }
  }

  void skip_rest_of_line() { rest_ = std::string_view(); }
  std::string_view line() const { return line_; }
  std::size_t line_number() const { return line_number_; }
  // Bytes after the current line.
  std::size_t bytes_left() const { return text_.size() - position_; }
  // Bytes of the current line that next_token() has not passed yet.
  std::size_t rest_of_line_size() const { return rest_.size(); }
  // Offset in `text` of the line after the current one.
  std::size_t next_line_offset() const { return position_; }

  [[noreturn]] void fail(const std::string& why) const { fail_at(line_number_, why); }
  [[noreturn]] void fail_at(std::size_t line_number, const std::string& why) const
  {
    fail_file("line " + std::to_string(line_number) + ": " + why);
  }
  // A problem of the whole file, not of one line.
  [[noreturn]] void fail_file(const std::string& why) const
  {
    throw File_error("'" + name_ + "' is not a valid ." + ext_ + " file (" + why + ")");
  }

private:
  std::string_view text_;
  std::string name_;
  std::string ext_;
  std::size_t position_ = 0;
  std::size_t line_number_ = 0;
  std::string_view line_, rest_;
};

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_TEXT_SCANNER_H
