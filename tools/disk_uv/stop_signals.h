// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the disk_uv tool stops on SIGINT, SIGTERM and SIGHUP, in every phase
// alike: the first signal is only noted, and the run stops at its next
// check (a progress report of the library, an output written, a block of an
// output written), removes its temporary files and says so on one line. A
// second signal ends the tool at once: the handler removes every temporary
// file the run has open, says so, and lets the signal kill the process.
//
// The handler may only call async-signal-safe code: the temporary files'
// names are kept in a table of atomic pointers that the writing fills and
// clears, sized before the first temporary is made, so that it holds any
// number of them.

#ifndef DISK_UV_STOP_SIGNALS_H
#define DISK_UV_STOP_SIGNALS_H

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <signal.h>
#include <unistd.h>

namespace disk_uv {

// Thrown where the tool notices a stop signal while it writes its outputs.
struct Stopped_while_writing : std::runtime_error
{
  Stopped_while_writing() : std::runtime_error("stopped while writing") {}
};

class Stop_signals
{
public:
  // Installs the handler for the signals that are not ignored (a background
  // job started with SIGINT ignored keeps it ignored).
  static void install()
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = &Stop_signals::handle;
    sigemptyset(&action.sa_mask);
    // SA_RESTART: a read or write goes on; the run stops at its next check.
    action.sa_flags = SA_RESTART;
    for(int signal_number : { SIGINT, SIGTERM, SIGHUP })
    {
      struct sigaction current;
      if(sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler != SIG_IGN)
        sigaction(signal_number, &action, nullptr);
    }
  }

  // The first signal received, or 0.
  static int received() { return first_signal(); }

  static std::string name()
  {
    switch(first_signal())
    {
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "SIGINT (Ctrl-C)";
    }
  }

  // The exit status of a run stopped by the signal: 128 + its number.
  static int exit_status() { return 128 + (first_signal() != 0 ? int(first_signal()) : SIGINT); }

  // Makes room for `count` temporary files, numbered 0 to count - 1. Called
  // before any of them exists; the table is never freed while the handler
  // may read it (one table a run, kept to the end).
  static void reserve_temporaries(std::size_t count)
  {
    std::unique_ptr<std::atomic<const char*>[]> table(new std::atomic<const char*>[count]);
    for(std::size_t i = 0; i < count; ++i)
      table[i].store(nullptr);
    table_size().store(0);
    table_pointer().store(table.get());
    table_size().store(count);
    kept_tables().push_back(std::move(table));
  }

  // `path` (which must stay valid until cleared) is removed by a second
  // signal. Set before the file is created, cleared once it was renamed.
  static void set_temporary(std::size_t slot, const char* path) { table_pointer().load()[slot].store(path); }
  static void clear_temporary(std::size_t slot)
  {
    if(std::atomic<const char*>* table = table_pointer().load())
      table[slot].store(nullptr);
  }

private:
  static volatile std::sig_atomic_t& first_signal()
  {
    static volatile std::sig_atomic_t value = 0;
    return value;
  }
  static std::atomic<std::atomic<const char*>*>& table_pointer()
  {
    static std::atomic<std::atomic<const char*>*> pointer(nullptr);
    return pointer;
  }
  static std::atomic<std::size_t>& table_size()
  {
    static std::atomic<std::size_t> size(0);
    return size;
  }
  static std::vector<std::unique_ptr<std::atomic<const char*>[]> >& kept_tables()
  {
    static std::vector<std::unique_ptr<std::atomic<const char*>[]> > tables;
    return tables;
  }

  static void write_error(const char* text)
  {
    const std::size_t length = std::strlen(text);
    if(::write(2, text, length) < 0) {}
  }

  static void handle(int signal_number)
  {
    if(first_signal() == 0)
    {
      first_signal() = signal_number;
      return;
    }
    const int saved_errno = errno;
    std::atomic<const char*>* table = table_pointer().load();
    const std::size_t size = table_size().load();
    for(std::size_t i = 0; table != nullptr && i < size; ++i)
      if(const char* path = table[i].load())
        ::unlink(path);
    write_error("\ndisk_uv: stopped at once by a second signal; its temporary files were removed\n");
    errno = saved_errno;
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
  }
};

} // namespace disk_uv

#endif // DISK_UV_STOP_SIGNALS_H
