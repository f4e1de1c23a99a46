// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The disk_uv tool's outputs as one transaction: every output path is
// checked before any work is done, every output is written to a temporary
// file beside its target, and the targets are replaced only once all of
// them were written. A failed run leaves every file the user had as it was.
//
// What the file system allows: the renames at the end are each atomic, but
// not all together (a crash between two renames replaces some outputs
// only), and the temporary files are not synced to disk before they are
// renamed. Outputs that are not regular files (/dev/null, a pipe, a
// terminal) are written through, after all temporary files were written and
// before any rename; what was written to them cannot be taken back.

#ifndef DISK_UV_OUTPUT_FILES_H
#define DISK_UV_OUTPUT_FILES_H

#include "tool_error.h"

#include "stop_signals.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

namespace disk_uv {

namespace internal {

// An output stream buffer over a file descriptor that remembers the first
// write error, so that "disk full" is reported rather than lost.
class Descriptor_buffer : public std::streambuf
{
public:
  explicit Descriptor_buffer(int fd) : fd_(fd), buffer_(1 << 16) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  int error() const { return error_; }

protected:
  int_type overflow(int_type c) override
  {
    if(!flush_buffer())
      return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof()))
    {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return flush_buffer() ? 0 : -1; }

private:
  bool flush_buffer()
  {
    const char* data = pbase();
    std::size_t left = std::size_t(pptr() - pbase());
    // Each pass writes a byte or more or sets error_; only a signal (EINTR)
    // repeats one without progress.
    while(left > 0 && error_ == 0)
    {
      // A stop signal ends a long output at its next block.
      if(Stop_signals::received() != 0)
      {
        error_ = EINTR;
        break;
      }
      const ssize_t written = ::write(fd_, data, left);
      if(written < 0 && errno == EINTR)
        continue;
      if(written <= 0)
        error_ = written < 0 ? errno : EIO;
      else
      {
        data += written;
        left -= std::size_t(written);
      }
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_ == 0;
  }

  int fd_;
  int error_ = 0;
  std::vector<char> buffer_;
};

inline std::string system_error_text(int error) { return std::strerror(error); }

inline std::string directory_of(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  if(slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

inline std::string file_name_of(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

inline std::string canonical_path(const std::string& path)
{
  char resolved[PATH_MAX];
  if(::realpath(path.c_str(), resolved) == nullptr)
    return std::string();
  return resolved;
}

// The marker between a temporary file's name prefix and its process id.
constexpr const char* temporary_marker = ".disk_uv-";

// The start of the names of the temporary files beside `name` in `folder`:
// ".NAME.disk_uv-", then the process id and an attempt number. A name too
// long for the folder (NAME_MAX, 255 bytes on most file systems) keeps only
// its first bytes, cut before a UTF-8 character, so that any legal output
// name gets a temporary name.
inline std::string temporary_prefix(const std::string& folder, const std::string& name)
{
  const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const std::size_t name_max = limit > 0 ? static_cast<std::size_t>(limit) : 255;
  // ".", ".disk_uv-", a pid of up to 10 digits, "-" and an attempt of up to 2.
  const std::size_t room = name_max > 23 ? name_max - 23 : 0;
  std::size_t keep = (std::min)(name.size(), room);
  while(keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xc0) == 0x80)
    --keep;
  return "." + name.substr(0, keep) + temporary_marker;
}

// Removes the temporary files PREFIXPID-N in `folder` (PREFIX as
// temporary_prefix() makes it) whose PREFIX `ours` accepts and whose
// process is gone: a run killed (SIGKILL, a power cut) while writing leaves
// them, full-size. Files of a live process, or named otherwise, stay. One
// pass over the folder, whatever the number of outputs in it.
template <typename Accept>
void remove_stale_temporaries(const std::string& folder, const Accept& ours)
{
  DIR* dir = ::opendir(folder.c_str());
  if(dir == nullptr)
    return;
  const std::string marker = temporary_marker;
  while(const dirent* entry = ::readdir(dir))
  {
    const std::string name = entry->d_name;
    const std::size_t at = name.rfind(marker);
    if(name.empty() || name[0] != '.' || at == std::string::npos || at == 0)
      continue;
    const std::string rest = name.substr(at + marker.size());
    const std::size_t dash = rest.find('-');
    if(dash == 0 || dash == std::string::npos || dash + 1 == rest.size() ||
       rest.find_first_not_of("0123456789-") != std::string::npos || rest.find('-', dash + 1) != std::string::npos ||
       dash > 10 || !ours(name.substr(0, at + marker.size())))
      continue;
    const long pid = std::strtol(rest.c_str(), nullptr, 10);
    if(pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      ::unlink((folder + "/" + name).c_str());
  }
  ::closedir(dir);
}

} // namespace internal

// The outputs of one run; see the top of this file.
class Output_files
{
public:
  typedef std::function<void(std::ostream&)> Writer;

  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files() { discard(); }

  // A file the run reads, which no output may replace: its path and what
  // it is to the user ("the input file", "the --material-ids file").
  struct Read_file
  {
    std::string path, role;
  };

  // Checks `path`, given with `option`, before any work: it must be a
  // writable regular file or a new file in a writable folder (followed
  // through symbolic links), or something written through such as
  // /dev/null or a pipe with a reader. It must not be a file the run reads
  // (under any spelling: the same device and inode), nor the same file as
  // another output. Throws Tool_error naming the problem.
  void add(const std::string& option, const std::string& path, const std::vector<Read_file>& read_files)
  {
    Output o;
    o.option = option;
    o.path = path;
    if(path.empty())
      fail(o, "the file name is empty");
    struct stat link_status, status;
    if(::lstat(path.c_str(), &link_status) != 0)
    {
      if(errno != ENOENT)
        fail(o, internal::system_error_text(errno));
      prepare_new_file(o);
    }
    else if(::stat(path.c_str(), &status) != 0)
      fail(o, "it is a symbolic link to a missing file");
    else if(S_ISDIR(status.st_mode))
      fail(o, "it is a folder");
    else if(S_ISREG(status.st_mode))
      prepare_replacement(o, status);
    else if(S_ISCHR(status.st_mode) || S_ISFIFO(status.st_mode))
      prepare_write_through(o, status);
    else
      fail(o, "it is neither a regular file, a character device nor a pipe");

    for(const Read_file& input : read_files)
    {
      struct stat input_status;
      if(o.exists && ::stat(input.path.c_str(), &input_status) == 0 && input_status.st_dev == o.device &&
         input_status.st_ino == o.inode)
        fail(o, "it is " + input.role);
    }
    // A device such as /dev/null may take several outputs.
    if(!(o.write_through && S_ISCHR(status.st_mode)))
    {
      const auto known = output_of_file_.emplace(o.file_key(), outputs_.size());
      if(!known.second)
        throw Tool_error("'" + path + "' is given to both " + outputs_[known.first->second].option + " and " +
                         option + "; one file cannot hold both outputs");
    }
    outputs_.push_back(std::move(o));
  }

  // Writes every output added, in the order added, through `writers` (one
  // per output), then replaces the targets. On any failure, or a stop
  // signal before the targets are replaced (Stopped_while_writing), no
  // target has been replaced and no temporary file is left. Once the
  // replacing has begun, a signal no longer stops it.
  void write_all(const std::vector<Writer>& writers)
  {
    if(writers.size() != outputs_.size())
      throw std::logic_error("Output_files::write_all: one writer per output is needed");
    Stop_signals::reserve_temporaries(outputs_.size());
    remove_stale_temporaries();
    for(std::size_t i = 0; i < outputs_.size(); ++i)
      if(!outputs_[i].write_through)
        write_temporary(i, writers[i]);
    for(std::size_t i = 0; i < outputs_.size(); ++i)
      if(outputs_[i].write_through)
        write_through(outputs_[i], writers[i]);
    stop_if_signalled();
    for(std::size_t i = 0; i < outputs_.size(); ++i)
    {
      Output& o = outputs_[i];
      if(o.write_through)
        continue;
      if(::rename(o.temporary.c_str(), o.target.c_str()) != 0)
      {
        const int error = errno;
        std::string replaced;
        for(std::size_t j = 0; j < i; ++j)
          if(!outputs_[j].write_through)
            replaced += (replaced.empty() ? "" : ", ") + outputs_[j].path;
        throw Tool_error("cannot replace '" + o.path + "' (" + internal::system_error_text(error) + ")" +
                         (replaced.empty() ? std::string() : "; already replaced: " + replaced));
      }
      forget_temporary(i);
    }
  }

  std::size_t size() const { return outputs_.size(); }

  // Temporaries left in `folder` by killed runs for files named as
  // `accepts` says (e.g. the UDIM pictures of an earlier run's pages) are
  // removed too, before the writing.
  void remove_stale_temporaries_of(const std::string& folder, std::function<bool(const std::string&)> accepts)
  {
    stale_names_.emplace_back(folder, std::move(accepts));
  }

private:
  struct Output
  {
    std::string option, path;
    std::string target;       // the file replaced (symbolic links followed)
    std::string identity;     // canonical path of a file that does not exist yet
    std::string temporary;
    bool exists = false;
    bool write_through = false;
    dev_t device = 0;
    ino_t inode = 0;
    mode_t mode = 0;
    uid_t owner = 0;
    gid_t group = 0;
    int descriptor = -1;      // open write-through target

    // The same for two outputs exactly when they name one file.
    std::string file_key() const
    {
      return exists ? "inode " + std::to_string(device) + ":" + std::to_string(inode) : "new " + identity;
    }
  };

  [[noreturn]] static void fail(const Output& o, const std::string& why)
  {
    throw Tool_error("cannot write " + o.option + " '" + o.path + "': " + why);
  }

  static void check_folder(const Output& o, const std::string& folder)
  {
    struct stat status;
    if(::stat(folder.c_str(), &status) != 0)
      fail(o, "its folder '" + folder + "' does not exist");
    if(!S_ISDIR(status.st_mode))
      fail(o, "'" + folder + "' is not a folder");
    if(::access(folder.c_str(), W_OK | X_OK) != 0)
      fail(o, "its folder '" + folder + "' is not writable");
  }

  static void prepare_new_file(Output& o)
  {
    const std::string folder = internal::directory_of(o.path);
    check_folder(o, folder);
    o.target = o.path;
    o.identity = internal::canonical_path(folder) + "/" + internal::file_name_of(o.path);
  }

  static void prepare_replacement(Output& o, const struct stat& status)
  {
    // Replace the file a symbolic link points to, keeping the link.
    o.target = internal::canonical_path(o.path);
    if(o.target.empty())
      fail(o, internal::system_error_text(errno));
    check_folder(o, internal::directory_of(o.target));
    if(::access(o.target.c_str(), W_OK) != 0)
      fail(o, "it is not writable");
    o.exists = true;
    o.device = status.st_dev;
    o.inode = status.st_ino;
    o.mode = status.st_mode & 07777;
    o.owner = status.st_uid;
    o.group = status.st_gid;
  }

  static void prepare_write_through(Output& o, const struct stat& status)
  {
    o.exists = true;
    o.write_through = true;
    o.device = status.st_dev;
    o.inode = status.st_ino;
    // Non-blocking open: a pipe without reader fails at once instead of
    // blocking the tool.
    o.descriptor = ::open(o.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
    if(o.descriptor < 0)
      fail(o, errno == ENXIO ? std::string("it is a pipe that nobody reads") : internal::system_error_text(errno));
    const int flags = ::fcntl(o.descriptor, F_GETFL);
    if(flags < 0 || ::fcntl(o.descriptor, F_SETFL, flags & ~O_NONBLOCK) != 0)
      fail(o, internal::system_error_text(errno));
  }

  // Writes `writer`'s output to `fd` and closes it; returns the first error.
  static int write_and_close(int fd, const Writer& writer)
  {
    int error = 0;
    {
      internal::Descriptor_buffer buffer(fd);
      std::ostream out(&buffer);
      try
      {
        writer(out);
        out.flush();
      }
      catch(...)
      {
        ::close(fd);
        throw;
      }
      error = buffer.error();
      if(error == 0 && !out)
        error = EIO;
    }
    if(::close(fd) != 0 && error == 0)
      error = errno;
    return error;
  }

  // The temporaries that killed runs left for our targets, and for the
  // names stale_names_ accepts in their folders.
  void remove_stale_temporaries() const
  {
    std::map<std::string, std::set<std::string> > prefixes_by_folder;
    for(const Output& o : outputs_)
      if(!o.write_through)
      {
        const std::string folder = internal::directory_of(o.target);
        prefixes_by_folder[folder].insert(internal::temporary_prefix(folder, internal::file_name_of(o.target)));
      }
    for(const auto& names : stale_names_)
      prefixes_by_folder[names.first];
    for(const auto& folder : prefixes_by_folder)
      internal::remove_stale_temporaries(folder.first, [&](const std::string& prefix) {
        if(folder.second.count(prefix) > 0)
          return true;
        // ".NAME.disk_uv-": NAME is what stale_names_ judges.
        const std::string name = prefix.substr(1, prefix.size() - 1 - std::strlen(internal::temporary_marker));
        for(const auto& names : stale_names_)
          if(names.first == folder.first && names.second(name))
            return true;
        return false;
      });
  }

  static void stop_if_signalled()
  {
    if(Stop_signals::received() != 0)
      throw Stopped_while_writing();
  }

  // Output `i`'s temporary name is no longer one to remove: renamed, or removed.
  void forget_temporary(std::size_t i)
  {
    Stop_signals::clear_temporary(i);
    outputs_[i].temporary.clear();
  }

  void write_temporary(std::size_t i, const Writer& writer)
  {
    stop_if_signalled();
    Output& o = outputs_[i];
    const std::string folder = internal::directory_of(o.target);
    const std::string prefix = internal::temporary_prefix(folder, internal::file_name_of(o.target));
    const std::string stem = folder + "/" + prefix + std::to_string(::getpid());
    int fd = -1;
    // At most 100 names; an error other than EEXIST ends it at once.
    for(int attempt = 0; attempt < 100 && fd < 0; ++attempt)
    {
      // Known to the signal handler before the file exists; never while the
      // name changes.
      Stop_signals::clear_temporary(i);
      o.temporary = stem + "-" + std::to_string(attempt);
      Stop_signals::set_temporary(i, o.temporary.c_str());
      // O_EXCL: never write into a file that is already there. Mode 0666
      // lets the umask decide, as for any new file.
      fd = ::open(o.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if(fd < 0 && errno != EEXIST)
        break;
    }
    if(fd < 0)
    {
      const int error = errno;
      forget_temporary(i);
      fail(o, "cannot create a temporary file in '" + folder + "' (" + internal::system_error_text(error) + ")");
    }
    if(o.exists)
    {
      // The replacement keeps the replaced file's permissions and, where
      // allowed, its owner.
      if(::fchown(fd, o.owner, o.group) != 0) {}
      ::fchmod(fd, o.mode);
    }
    const int error = write_and_close(fd, writer);
    stop_if_signalled();
    if(error != 0)
      throw Tool_error("error while writing '" + o.path + "': " + internal::system_error_text(error));
  }

  void write_through(Output& o, const Writer& writer)
  {
    const int fd = o.descriptor;
    o.descriptor = -1;
    const int error = write_and_close(fd, writer);
    stop_if_signalled();
    if(error != 0)
      throw Tool_error("error while writing '" + o.path + "': " + internal::system_error_text(error));
  }

  void discard()
  {
    for(std::size_t i = 0; i < outputs_.size(); ++i)
    {
      Output& o = outputs_[i];
      if(!o.temporary.empty())
      {
        ::unlink(o.temporary.c_str());
        forget_temporary(i);
      }
      if(o.descriptor >= 0)
        ::close(o.descriptor);
      o.descriptor = -1;
    }
  }

  std::vector<Output> outputs_;
  std::map<std::string, std::size_t> output_of_file_;
  std::vector<std::pair<std::string, std::function<bool(const std::string&)> > > stale_names_;
};

} // namespace disk_uv

#endif // DISK_UV_OUTPUT_FILES_H
