// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads the disk_uv tool's input file into memory, so that its readers
// always know how many bytes are left. Only regular files are read unless
// the caller allows other inputs: opening a FIFO without a writer blocks
// forever, and a device such as /dev/zero never ends.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_INPUT_FILE_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_INPUT_FILE_H

#include <CGAL/Disk_segmentation/IO/internal/Text_line_guard.h>
#include <CGAL/Disk_segmentation/IO/internal/Text_scanner.h>
#include <CGAL/Disk_segmentation/IO/File_error.h>

#include <cerrno>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <new>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {


inline const char* file_kind(mode_t mode)
{
  if(S_ISFIFO(mode))
    return "a FIFO";
  if(S_ISCHR(mode))
    return "a character device";
  if(S_ISBLK(mode))
    return "a block device";
  if(S_ISSOCK(mode))
    return "a socket";
  return "not a file";
}

class File_descriptor
{
public:
  explicit File_descriptor(int fd) : fd_(fd) {}
  File_descriptor(const File_descriptor&) = delete;
  File_descriptor& operator=(const File_descriptor&) = delete;
  ~File_descriptor() { if(fd_ >= 0) ::close(fd_); }
  int get() const { return fd_; }

private:
  int fd_;
};

// Appends at most `wanted` bytes of `fd` to `bytes`; returns the number
// read, less than `wanted` only at the end of the input.
inline std::size_t read_up_to(int fd, std::string& bytes, std::size_t wanted, const std::string& path)
{
  const std::size_t start = bytes.size();
  bytes.resize(start + wanted);
  // Each pass reads a byte or more, or ends (end of input, error); only a
  // signal (EINTR) repeats one without progress.
  std::size_t done = 0;
  while(done < wanted)
  {
    const ssize_t got = ::read(fd, &bytes[start + done], wanted - done);
    if(got < 0 && errno == EINTR)
      continue;
    if(got < 0)
      throw File_error("error while reading '" + path + "' (" + std::strerror(errno) + ")");
    if(got == 0)
      break;
    done += std::size_t(got);
  }
  bytes.resize(start + done);
  return done;
}


// The whole content of `path`. A regular file is read at its size; with
// `allow_special_input`, another input (a FIFO, a device, a socket) is read
// to its end, refused beyond `max_input_bytes`. With `format` (a mesh
// format's extension), a text line longer than max_line_bytes is refused
// as soon as it is read (Text_line_guard). Throws File_error.
inline std::string read_input_file(const std::string& path, bool allow_special_input,
                                   std::uint64_t max_input_bytes, const std::string& format = std::string())
{
  // stat() before open(): opening a FIFO without a writer would block.
  struct stat info;
  if(::stat(path.c_str(), &info) != 0)
    throw File_error("cannot open '" + path + "' for reading (" + std::strerror(errno) + ")");
  if(S_ISDIR(info.st_mode))
    throw File_error("'" + path + "' is a directory, not a mesh file");
  const bool regular = S_ISREG(info.st_mode);
  if(!regular && !allow_special_input)
    throw File_error("'" + path + "' is not a regular file (it is " + file_kind(info.st_mode) +
                     "); --allow-special-input reads it, up to " + size_text(max_input_bytes));

  // O_NONBLOCK: should the path have become a FIFO since stat(), open()
  // must not wait for a writer (it changes nothing for a regular file).
  const File_descriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | (regular ? O_NONBLOCK : 0)));
  if(fd.get() < 0)
    throw File_error("cannot open '" + path + "' for reading (" + std::strerror(errno) + ")");
  struct stat opened;
  if(::fstat(fd.get(), &opened) != 0 || bool(S_ISREG(opened.st_mode)) != regular)
    throw File_error("'" + path + "' changed while it was being opened");

  std::string bytes;
  // One byte over a line's limit: a file without a line break is refused
  // on its first read.
  const std::size_t chunk = max_line_bytes + 1;
  if(regular)
  {
    // A file that grows while it is read is taken at the size it had.
    const std::size_t size = std::size_t(opened.st_size);
    Text_line_guard guard(path, format, size);
    // Each pass reads a whole chunk or ends: at most size / chunk + 1 passes.
    while(bytes.size() < size)
    {
      const std::size_t wanted = (std::min)(chunk, size - bytes.size());
      const std::size_t got = read_up_to(fd.get(), bytes, wanted, path);
      if(!format.empty())
        guard.check(bytes);
      if(got < wanted)
        break;
      // Room for the whole file once two chunks passed the guard: a file
      // whose first line, or any line starting in its first MiB, is too
      // long never gets it.
      if(bytes.size() >= 2 * chunk && bytes.capacity() < size)
      {
        try
        {
          bytes.reserve(size);
        }
        catch(const std::bad_alloc&)
        {
          throw File_error("'" + path + "' (" + std::to_string(opened.st_size) + " bytes) does not fit in memory");
        }
      }
    }
    return bytes;
  }
  Text_line_guard guard(path, format, 0);
  // Each pass that goes on reads a whole chunk, and the input is refused
  // past max_input_bytes: at most max_input_bytes / chunk + 2 passes.
  for(;;)
  {
    const std::uint64_t room = max_input_bytes - bytes.size();
    // One byte beyond the limit tells a full input from a longer one.
    const std::size_t wanted = std::size_t(room < chunk ? room + 1 : chunk);
    const std::size_t got = read_up_to(fd.get(), bytes, wanted, path);
    if(!format.empty())
      guard.check(bytes);
    if(got < wanted)
      break;
    if(bytes.size() > max_input_bytes)
      throw File_error("'" + path + "' is longer than the limit of " + size_text(max_input_bytes) +
                       " for an input that is not a regular file");
  }
  return bytes;
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_INPUT_FILE_H
