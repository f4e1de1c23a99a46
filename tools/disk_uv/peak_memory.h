// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's peak memory, as its report gives it (peak_rss_mb). A measure
// of the process, not of the atlas: the library's report leaves it out.

#ifndef DISK_UV_PEAK_MEMORY_H
#define DISK_UV_PEAK_MEMORY_H

#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>

namespace disk_uv {

// The process's peak resident memory so far, in MB. Linux's VmHWM first:
// getrusage()'s ru_maxrss keeps the peak of the address space the process
// had before exec(), so a tool started from a large parent (a Python
// script holding 400 MB, through vfork) reported the parent's peak.
inline double peak_rss_mb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, 6, "VmHWM:") == 0)
    {
      std::istringstream kilobytes(line.substr(6));
      double kb = 0;
      if(kilobytes >> kb)
        return kb / 1024.;
    }
  struct rusage usage;
  if(::getrusage(RUSAGE_SELF, &usage) != 0)
    return 0;
  return double(usage.ru_maxrss) / 1024.;  // KB on Linux
}

} // namespace disk_uv

#endif // DISK_UV_PEAK_MEMORY_H
