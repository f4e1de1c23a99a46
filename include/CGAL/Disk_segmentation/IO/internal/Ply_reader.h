// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The disk_uv tool's strict reader of PLY polygon soups (ascii,
// binary_little_endian and binary_big_endian 1.0), parsing a file held in
// memory. Every count the header declares is checked against the bytes the
// file has left before anything is allocated for it, and every problem is
// named with its line (ASCII) or byte offset (binary).

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_PLY_READER_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_PLY_READER_H

#include <CGAL/Disk_segmentation/IO/internal/Text_scanner.h>
#include <CGAL/Disk_segmentation/IO/File_error.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// A PLY header takes a few hundred bytes, a few kB with long comments; no
// end_header line in the first MiB means the file is not PLY (or an input
// that does not end).
constexpr std::size_t max_ply_header_bytes = std::size_t(1) << 20;


enum class Ply_type { INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

struct Ply_type_info
{
  const char* name;
  const char* sized_name;
  Ply_type type;
  std::size_t size;
  double min, max;  // of the integer types, checked in ASCII files
};

inline const Ply_type_info& ply_type_info(Ply_type type)
{
  static const Ply_type_info types[] = {
    { "char", "int8", Ply_type::INT8, 1, -128., 127. },
    { "uchar", "uint8", Ply_type::UINT8, 1, 0., 255. },
    { "short", "int16", Ply_type::INT16, 2, -32768., 32767. },
    { "ushort", "uint16", Ply_type::UINT16, 2, 0., 65535. },
    { "int", "int32", Ply_type::INT32, 4, -2147483648., 2147483647. },
    { "uint", "uint32", Ply_type::UINT32, 4, 0., 4294967295. },
    { "float", "float32", Ply_type::FLOAT32, 4, 0., 0. },
    { "double", "float64", Ply_type::FLOAT64, 8, 0., 0. } };
  return types[int(type)];
}

inline bool ply_type_named(std::string_view name, Ply_type& type)
{
  for(int t = 0; t <= int(Ply_type::FLOAT64); ++t)
    if(name == ply_type_info(Ply_type(t)).name || name == ply_type_info(Ply_type(t)).sized_name)
    {
      type = Ply_type(t);
      return true;
    }
  return false;
}

struct Ply_property
{
  std::string name;
  bool is_list;
  Ply_type count_type;  // of a list
  Ply_type type;        // of the value, or of a list's entries
};

struct Ply_element
{
  std::string name;
  std::size_t count;
  std::size_t header_line;
  std::vector<Ply_property> properties;
};

// The values of a PLY body one after the other, ASCII or binary; failures
// name the line or byte and the element item being read.
class Ply_values
{
public:
  enum Format { ASCII, BINARY_LITTLE_ENDIAN, BINARY_BIG_ENDIAN };

  Ply_values(std::string_view body, std::size_t body_offset, std::size_t first_line, Format format,
             const std::string& name)
    : body_(body), body_offset_(body_offset), format_(format), text_(body, name, "ply", first_line)
  {}

  void at_item(const std::string& element, std::size_t item)
  {
    element_ = &element;
    item_ = item;
  }
  std::string item() const { return *element_ + " #" + std::to_string(item_); }
  Format format() const { return format_; }
  std::size_t bytes_left() const
  {
    return format_ == ASCII ? text_.rest_of_line_size() + text_.bytes_left() : body_.size() - position_;
  }

  double next(Ply_type type)
  {
    const Ply_type_info& info = ply_type_info(type);
    if(format_ == ASCII)
    {
      if(!text_.next_token(token_))
        fail("the file ends in " + item());
      if(type == Ply_type::FLOAT32 || type == Ply_type::FLOAT64)
      {
        float single = 0;
        double value = 0;
        const bool ok = type == Ply_type::FLOAT32 ? parse_number(token_, single) : parse_number(token_, value);
        if(!ok)
          fail(item() + ": " + quote_token(token_) + " is not a number");
        return type == Ply_type::FLOAT32 ? double(single) : value;
      }
      long long value = 0;
      bool overflow = false;
      if(!parse_integer(token_, value, overflow) || double(value) < info.min || double(value) > info.max)
        fail(item() + ": " + quote_token(token_) + " is not a " + info.name + " (an integer from " +
             std::to_string((long long)info.min) + " to " + std::to_string((long long)info.max) + ")");
      return double(value);
    }
    last_position_ = position_;
    if(info.size > body_.size() - position_)
      fail("the file ends in " + item());
    std::uint64_t bits = 0;
    for(std::size_t i = 0; i < info.size; ++i)
    {
      const std::size_t byte = format_ == BINARY_LITTLE_ENDIAN ? info.size - 1 - i : i;
      bits = bits << 8 | static_cast<unsigned char>(body_[position_ + byte]);
    }
    position_ += info.size;
    switch(type)
    {
      case Ply_type::INT8: return double(std::int8_t(bits));
      case Ply_type::INT16: return double(std::int16_t(bits));
      case Ply_type::INT32: return double(std::int32_t(bits));
      case Ply_type::FLOAT32:
      {
        const std::uint32_t narrow = std::uint32_t(bits);
        float value;
        std::memcpy(&value, &narrow, sizeof(value));
        return double(value);
      }
      case Ply_type::FLOAT64:
      {
        double value;
        std::memcpy(&value, &bits, sizeof(value));
        return value;
      }
      default: return double(bits);
    }
  }

  // The last value read as the file has it, for messages.
  std::string last_value(double value) const
  {
    if(format_ == ASCII)
      return quote_token(token_);
    if(value == std::floor(value) && std::fabs(value) < 1e15)
      return "'" + std::to_string((long long)value) + "'";
    return "'" + std::to_string(value) + "'";
  }

  // A count in the header too small would leave values unread.
  void expect_end()
  {
    std::string_view token;
    last_position_ = position_;
    if(format_ == ASCII ? text_.next_token(token) : position_ != body_.size())
      fail("data after the last element (is a count in the header too small?)");
  }

  [[noreturn]] void fail(const std::string& why) const
  {
    if(format_ == ASCII)
      text_.fail(why);
    text_.fail_file("byte " + std::to_string(body_offset_ + last_position_) + ": " + why);
  }

private:
  std::string_view body_;
  std::size_t body_offset_;
  Format format_;
  Text_scanner text_;
  std::string_view token_;
  std::size_t position_ = 0, last_position_ = 0;
  const std::string* element_ = nullptr;
  std::size_t item_ = 0;
};

// The index of the property of `element` named `name`, or its number of
// properties if it has none.
inline std::size_t ply_property_index(const Ply_element& element, const char* name)
{
  std::size_t k = 0;
  while(k < element.properties.size() && element.properties[k].name != name)
    ++k;
  return k;
}

// The header of a PLY file, up to its end_header line: its format and its
// elements, in order. Throws File_error (through `header`) on anything it
// does not read. `total_size` is the size of the whole file.
inline std::vector<Ply_element> read_ply_header(Text_scanner& header, std::string_view header_text,
                                                std::size_t total_size, Ply_values::Format& format)
{
  std::vector<std::string_view> tokens;
  if(!header.next_tokens(tokens, '\0'))
    header.fail_file("it is empty");
  if(header.line_number() != 1 || tokens.size() != 1 || tokens[0] != "ply")
    header.fail("the file does not start with a 'ply' line");
  if(!header.next_line())
    header.fail_file("the header ends after its first line");
  split_tokens(header.line(), tokens, '\0');
  format = Ply_values::ASCII;
  double version = 0;
  if(tokens.size() != 3 || tokens[0] != "format")
    header.fail("expected 'format ascii 1.0' (or binary_little_endian, binary_big_endian), found " +
                quote_token(header.line()));
  if(tokens[1] == "binary_little_endian")
    format = Ply_values::BINARY_LITTLE_ENDIAN;
  else if(tokens[1] == "binary_big_endian")
    format = Ply_values::BINARY_BIG_ENDIAN;
  else if(tokens[1] != "ascii")
    header.fail("unknown format " + quote_token(tokens[1]) + " (ascii, binary_little_endian or binary_big_endian)");
  if(!parse_number(tokens[2], version) || version != 1.0)
    header.fail("unsupported PLY version " + quote_token(tokens[2]) + " (1.0 is read)");

  std::vector<Ply_element> elements;
  bool header_ended = false;
  // Each pass takes a line of the header's first MiB.
  while(!header_ended && header.next_line())
  {
    if(header.next_line_offset() == header_text.size() && header_text.size() < total_size &&
       header_text.back() != '\n')
      break;  // a line cut by the header limit
    split_tokens(header.line(), tokens, '\0');
    if(tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info")
      continue;
    if(tokens[0] == "end_header")
      header_ended = true;
    else if(tokens[0] == "element")
    {
      std::size_t count = 0;
      if(tokens.size() != 3 || !parse_index(tokens[2], count))
        header.fail("expected 'element NAME COUNT', found " + quote_token(header.line()));
      elements.push_back({ std::string(tokens[1]), count, header.line_number(), {} });
    }
    else if(tokens[0] == "property")
    {
      if(elements.empty())
        header.fail("a property comes before any element");
      const bool is_list = tokens.size() >= 2 && tokens[1] == "list";
      if(tokens.size() != (is_list ? 5u : 3u))
        header.fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME', found " +
                    quote_token(header.line()));
      Ply_property property{ std::string(tokens.back()), is_list, Ply_type::UINT8, Ply_type::UINT8 };
      if(is_list && !ply_type_named(tokens[2], property.count_type))
        header.fail("unknown list count type " + quote_token(tokens[2]));
      if(!ply_type_named(tokens[tokens.size() - 2], property.type))
        header.fail("unknown property type " + quote_token(tokens[tokens.size() - 2]));
      elements.back().properties.push_back(property);
    }
    else
      header.fail("unknown header keyword " + quote_token(tokens[0]));
  }
  if(!header_ended)
    header.fail_file(total_size > max_ply_header_bytes
                       ? "no end_header line in its first " + size_text(max_ply_header_bytes)
                       : std::string("the header has no end_header line"));
  return elements;
}

// Every item takes a minimum number of bytes: the counts must fit in the
// body before anything is allocated for them.
inline void check_ply_counts(const Text_scanner& header, const std::vector<Ply_element>& elements,
                             Ply_values::Format format, std::size_t body_size)
{
  std::size_t needed = 0;
  for(const Ply_element& element : elements)
  {
    std::size_t item_bytes = 0;  // ASCII: a token and a blank per value
    for(const Ply_property& p : element.properties)
      item_bytes += format == Ply_values::ASCII ? 2 : ply_type_info(p.is_list ? p.count_type : p.type).size;
    if(item_bytes != 0 && (element.count > (body_size + 1) / item_bytes ||
                           needed + element.count * item_bytes > body_size + 1))
      header.fail_at(element.header_line, std::to_string(element.count) + " items of element " +
                                            quote_token(element.name) + " do not fit in the " +
                                            std::to_string(body_size) + " bytes after the header");
    needed += element.count * item_bytes;
  }
}

// What the reader takes from an element: the properties of a vertex
// element's x, y and z, and a face element's list of vertex indices (the
// number of properties where there is none).
struct Ply_element_roles
{
  bool is_vertex, is_face;
  std::size_t xyz_index[3] = { 0, 0, 0 };
  std::size_t face_list;

  Ply_element_roles(const Text_scanner& header, const Ply_element& element)
    : is_vertex(element.name == "vertex" || element.name == "vertices"),
      is_face(element.name == "face" || element.name == "faces"), face_list(element.properties.size())
  {
    if(is_vertex)
      for(int i = 0; i < 3; ++i)
      {
        const char* coordinate = i == 0 ? "x" : i == 1 ? "y" : "z";
        xyz_index[i] = ply_property_index(element, coordinate);
        if(xyz_index[i] == element.properties.size() || element.properties[xyz_index[i]].is_list)
          header.fail_at(element.header_line, "element " + quote_token(element.name) + " has no scalar property '" +
                                                coordinate + "'");
      }
    if(is_face)
    {
      face_list = ply_property_index(element, "vertex_indices");
      if(face_list == element.properties.size())
        face_list = ply_property_index(element, "vertex_index");
      if(face_list == element.properties.size() || !element.properties[face_list].is_list)
        header.fail_at(element.header_line, "element " + quote_token(element.name) +
                                              " has no list property 'vertex_indices' (or 'vertex_index')");
    }
  }
};

// Reads a list property of the current item; its entries go to `polygon`
// if it is the face list. Its length was checked against the bytes left,
// and every value read takes at least one byte.
inline void read_ply_list(Ply_values& values, const Ply_property& property, bool is_face_list,
                          std::vector<std::size_t>& polygon)
{
  const double length = values.next(property.count_type);
  // ASCII: an entry and a blank; the file's last entry may lack the blank.
  const std::size_t most_entries = values.format() == Ply_values::ASCII
                                     ? (values.bytes_left() + 1) / 2
                                     : values.bytes_left() / ply_type_info(property.type).size;
  if(length < 0 || length != std::floor(length))
    values.fail(values.item() + ": the list '" + property.name + "' has the length " +
                values.last_value(length) + (length < 0 ? ", a negative count" : ", not a whole number"));
  if(length > double(most_entries))
    values.fail(values.item() + ": the list '" + property.name + "' declares " +
                std::to_string((unsigned long long)length) + " entries, more than the " +
                std::to_string(values.bytes_left()) + " bytes left in the file hold");
  if(is_face_list)
    polygon.resize(std::size_t(length));
  for(std::size_t i = 0; i < std::size_t(length); ++i)
  {
    const double entry = values.next(property.type);
    if(!is_face_list)
      continue;
    if(entry < 0 || entry != std::floor(entry) || entry > 9007199254740992.)
      values.fail(values.item() + " has the index " + values.last_value(entry) + ", which is not a vertex index");
    polygon[i] = std::size_t(entry);
  }
}

// Reads a PLY file: the `vertex` (or `vertices`) element's x, y and z, of
// any scalar type, and the `face` (or `faces`) element's `vertex_indices`
// (or `vertex_index`) list, of any count and index type; elements may come
// in any order, and other elements and properties are skipped.
template <typename Point>
void read_PLY_soup(std::string_view bytes, const std::string& name, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons)
{
  const std::string_view header_text = bytes.substr(0, max_ply_header_bytes);
  Text_scanner header(header_text, name, "ply");
  Ply_values::Format format = Ply_values::ASCII;
  const std::vector<Ply_element> elements = read_ply_header(header, header_text, bytes.size(), format);
  const std::size_t body_offset = header.next_line_offset();
  check_ply_counts(header, elements, format, bytes.size() - body_offset);

  Ply_values values(bytes.substr(body_offset), body_offset, header.line_number() + 1, format, name);
  bool vertices_seen = false, faces_seen = false;
  for(const Ply_element& element : elements)
  {
    const Ply_element_roles roles(header, element);
    vertices_seen = vertices_seen || roles.is_vertex;
    faces_seen = faces_seen || roles.is_face;
    if(element.properties.empty())
      continue;
    if(roles.is_vertex)
      points.reserve(points.size() + element.count);
    if(roles.is_face)
      polygons.reserve(polygons.size() + element.count);

    // element.count was checked against the bytes left.
    double xyz[3] = { 0, 0, 0 };
    for(std::size_t item = 0; item < element.count; ++item)
    {
      values.at_item(element.name, item);
      std::vector<std::size_t> polygon;
      for(std::size_t k = 0; k < element.properties.size(); ++k)
      {
        const Ply_property& property = element.properties[k];
        if(property.is_list)
        {
          read_ply_list(values, property, k == roles.face_list, polygon);
          continue;
        }
        const double value = values.next(property.type);
        for(int i = 0; i < 3; ++i)
          if(roles.is_vertex && k == roles.xyz_index[i])
          {
            if(!std::isfinite(value))
              values.fail(values.item() + " has a non-finite coordinate " + values.last_value(value));
            xyz[i] = value;
          }
      }
      if(roles.is_vertex)
        points.emplace_back(xyz[0], xyz[1], xyz[2]);
      if(roles.is_face)
        polygons.push_back(std::move(polygon));
    }
  }
  values.expect_end();
  if(!vertices_seen)
    header.fail_file("it has no vertex element");
  if(!faces_seen)
    header.fail_file("it has no face element");
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_PLY_READER_H
