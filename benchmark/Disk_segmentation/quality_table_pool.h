// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_table, the parent's side: the pool of forked children, at most
// --jobs at once, each killed past --time-limit, and what they reported.

#ifndef DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_POOL_H
#define DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_POOL_H

#include "quality_table_case.h"
#include "quality_table_support.h"

namespace {

// ---------------------------------------------------------------------------
// The parent: the pool of child processes

struct Running
{
  std::size_t index = 0;
  pid_t pid = -1;
  int fd = -1;
  bool eof = false;
  Clock::time_point start, deadline;
  std::string buffer;
};

void consume_lines(Running& r, Result& result, bool flush)
{
  std::size_t begin = 0;
  for(;;)
  {
    std::size_t end = r.buffer.find('\n', begin);
    if(end == std::string::npos)
    {
      if(!flush || begin >= r.buffer.size())
        break;
      end = r.buffer.size();
    }
    const std::string line = r.buffer.substr(begin, end - begin);
    begin = (end < r.buffer.size()) ? end + 1 : end;
    if(line.empty())
      continue;
    if(line.compare(0, 3, "@@\t") == 0)
    {
      const std::size_t tab = line.find('\t', 3);
      if(tab != std::string::npos)
        result.values[line.substr(3, tab - 3)] = line.substr(tab + 1);
    }
    else
    {
      result.stderr_tail = one_line(line);
      if(result.stderr_tail.size() > 300)
        result.stderr_tail.resize(300);
    }
  }
  r.buffer.erase(0, begin);
}

std::string signal_name(int sig)
{
  const char* name = ::strsignal(sig);
  return name ? std::string(name) : std::string("?");
}

void finish(Running& r, int status, bool timed_out, double time_limit, Result& result)
{
  consume_lines(r, result, true);
  result.wall_seconds = seconds_since(r.start);
  if(timed_out)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "time-out after %g s", time_limit);
    result.fail("time-out", text);
  }
  else if(WIFSIGNALED(status))
  {
    std::string reason = "crashed (signal " + std::to_string(WTERMSIG(status)) + ", " + signal_name(WTERMSIG(status)) + ")";
    if(!result.stderr_tail.empty())
      reason += ": " + result.stderr_tail;
    result.fail("crash", reason);
  }
  else if(WIFEXITED(status) && (WEXITSTATUS(status) != 0 || !result.has("done")))
  {
    std::string reason = "child exited with status " + std::to_string(WEXITSTATUS(status));
    if(!result.has("done"))
      reason += " before it finished";
    if(!result.stderr_tail.empty())
      reason += ": " + result.stderr_tail;
    result.fail("crash", reason);
  }
  ::close(r.fd);
}

// Starts the child of `c`; returns false if fork or pipe failed.
bool start_child(const Options& o, const std::vector<fs::path>& files, const std::vector<Case>& cases,
                 std::size_t index, Running& r)
{
  int fds[2];
  if(::pipe(fds) != 0)
    return false;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return false;
  }
  if(pid == 0)
  {
    // Child: stdout and stderr into the pipe, stdin from /dev/null.
    ::close(fds[0]);
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    const int null = ::open("/dev/null", O_RDONLY);
    if(null >= 0)
      ::dup2(null, STDIN_FILENO);
    const Reporter report{ fds[1] };
    const Case& c = cases[index];
    Case_settings s{ files[c.mesh].string(), c.segmentation, c.method, o.seeds, o.threads, o.texture_resolution,
                     o.crease_penalty };
    try
    {
      run_case(s, report);
    }
    catch(const std::exception& e)
    {
      report("failure_kind", "exception");
      report("reason", std::string("uncaught: ") + e.what());
    }
    catch(...)
    {
      report("failure_kind", "exception");
      report("reason", "uncaught unknown exception");
    }
    report("done", "1");
    std::cout.flush();
    std::cerr.flush();
    ::_exit(0);
  }
  ::close(fds[1]);
  r.index = index;
  r.pid = pid;
  r.fd = fds[0];
  r.eof = false;
  r.buffer.clear();
  r.start = Clock::now();
  r.deadline = r.start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.time_limit));
  return true;
}

void run_all(const Options& o, const std::vector<fs::path>& files, const std::vector<Case>& cases,
             std::vector<Result>& results)
{
  results.assign(cases.size(), Result());
  std::vector<Running> running;
  std::size_t next = 0, finished = 0;
  auto progress = [&](std::size_t index) {
    ++finished;
    if(o.quiet)
      return;
    const Case& c = cases[index];
    const Result& r = results[index];
    std::cerr << "[" << finished << "/" << cases.size() << "] " << files[c.mesh].filename().string() << " "
              << c.segmentation << " " << DS::to_string(c.method) << ": ";
    if(r.input_error())
      std::cerr << "input error (" << r.get("input_error") << ")";
    else if(r.failed())
      std::cerr << "FAILED (" << r.get("reason") << ")";
    else
      std::cerr << "ok, " << r.get("charts") << " charts, " << r.get("flipped_percent") << "% flipped";
    std::cerr << ", " << format_double(std::round(r.wall_seconds * 100) / 100) << " s" << std::endl;
  };

  while(next < cases.size() || !running.empty())
  {
    while(running.size() < o.jobs && next < cases.size())
    {
      Running r;
      if(!start_child(o, files, cases, next, r))
      {
        if(running.empty())
        {
          results[next].fail("exception", std::string("cannot start a child process: ") + std::strerror(errno));
          progress(next);
          ++next;
          continue;
        }
        break;  // retry once a running child ends
      }
      running.push_back(r);
      ++next;
    }

    // Wait for output, or for the nearest deadline.
    const Clock::time_point now = Clock::now();
    Clock::time_point nearest = Clock::time_point::max();
    std::vector<pollfd> polled;
    bool pending_exit = false;
    for(const Running& r : running)
    {
      nearest = (std::min)(nearest, r.deadline);
      if(r.eof)
        pending_exit = true;
      else
        polled.push_back(pollfd{ r.fd, POLLIN, 0 });
    }
    long timeout_ms = nearest > now
      ? static_cast<long>(std::chrono::duration_cast<std::chrono::milliseconds>(nearest - now).count()) + 1
      : 0;
    if(pending_exit)
      timeout_ms = (std::min)(timeout_ms, 10L);
    timeout_ms = (std::min)(timeout_ms, 1000L);
    if(!polled.empty())
    {
      if(::poll(polled.data(), polled.size(), static_cast<int>(timeout_ms)) < 0 && errno != EINTR)
        throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    }
    else if(timeout_ms > 0)
      ::usleep(static_cast<useconds_t>(timeout_ms * 1000));

    for(const pollfd& p : polled)
    {
      if(!(p.revents & (POLLIN | POLLHUP | POLLERR)))
        continue;
      for(Running& r : running)
        if(r.fd == p.fd)
        {
          char chunk[65536];
          const ssize_t n = ::read(r.fd, chunk, sizeof(chunk));
          if(n > 0)
          {
            r.buffer.append(chunk, static_cast<std::size_t>(n));
            consume_lines(r, results[r.index], false);
          }
          else if(n == 0 || (errno != EINTR && errno != EAGAIN))
            r.eof = true;
        }
    }

    // Children that ended, or ran out of time.
    for(std::size_t i = 0; i < running.size();)
    {
      Running& r = running[i];
      int status = 0;
      bool done = false, timed_out = false;
      if(r.eof)
      {
        const pid_t w = ::waitpid(r.pid, &status, WNOHANG);
        done = (w == r.pid);
      }
      if(!done && Clock::now() >= r.deadline)
      {
        ::kill(r.pid, SIGKILL);
        ::waitpid(r.pid, &status, 0);
        done = true;
        timed_out = true;
      }
      if(done)
      {
        // Whatever the child wrote before it ended.
        char chunk[65536];
        ssize_t n;
        const int flags = ::fcntl(r.fd, F_GETFL);
        ::fcntl(r.fd, F_SETFL, flags | O_NONBLOCK);
        while((n = ::read(r.fd, chunk, sizeof(chunk))) > 0)
          r.buffer.append(chunk, static_cast<std::size_t>(n));
        finish(r, status, timed_out, o.time_limit, results[r.index]);
        progress(r.index);
        running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
      }
      else
        ++i;
    }
  }
}

} // namespace

#endif // DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_POOL_H
