// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrAvailableMemory.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>

namespace vr
{
namespace
{
/** A field of a /proc file of "Key: value kB" lines, in bytes; negative when absent. */
double
KibibyteField(const char * file, const std::string & field)
{
  std::ifstream stream(file);
  std::string   line;
  while (std::getline(stream, line))
  {
    if (line.compare(0, field.size() + 1, field + ":") == 0)
    {
      std::istringstream value(line.substr(field.size() + 1));
      double             kibibytes = -1.0;
      value >> kibibytes;
      return kibibytes >= 0.0 ? kibibytes * 1024.0 : -1.0;
    }
  }
  return -1.0;
}

/** One number from a cgroup file; negative for "max", a missing file or anything else. */
double
CgroupNumber(const std::string & file)
{
  std::ifstream stream(file);
  std::string   text;
  if (!(stream >> text) || text == "max")
  {
    return -1.0;
  }
  try
  {
    return std::stod(text);
  }
  catch (const std::exception &)
  {
    return -1.0;
  }
}

/** What is left below the memory limit of this process's cgroup (v2, the unified hierarchy) and of every cgroup above
 * it; negative when none sets one or they cannot be read. */
double
CgroupHeadroom()
{
  std::ifstream cgroups("/proc/self/cgroup");
  std::string   line;
  std::string   path;
  while (std::getline(cgroups, line))
  {
    if (line.compare(0, 3, "0::") == 0)
    {
      path = line.substr(3);
    }
  }
  if (path.empty() || path[0] != '/')
  {
    return -1.0;
  }
  double headroom = -1.0;
  for (;;)
  {
    const std::string folder = "/sys/fs/cgroup" + (path == "/" ? std::string() : path);
    const double      limit = CgroupNumber(folder + "/memory.max");
    const double      used = CgroupNumber(folder + "/memory.current");
    if (limit >= 0.0 && used >= 0.0)
    {
      const double left = std::max(0.0, limit - used);
      headroom = headroom < 0.0 ? left : std::min(headroom, left);
    }
    if (path == "/")
    {
      return headroom;
    }
    const auto slash = path.find_last_of('/');
    path = slash == 0 ? "/" : path.substr(0, slash);
  }
}

/** What is left of the address-space limit (RLIMIT_AS); negative without one. */
double
AddressSpaceHeadroom()
{
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
  {
    return -1.0;
  }
  const double used = KibibyteField("/proc/self/status", "VmSize");
  return std::max(0.0, static_cast<double>(limit.rlim_cur) - std::max(used, 0.0));
}
} // namespace

double
AvailableMemoryInBytes()
{
  double available = KibibyteField("/proc/meminfo", "MemAvailable");
  if (available < 0.0)
  {
    const long pages = ::sysconf(_SC_AVPHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    available = pages > 0 && pageSize > 0 ? static_cast<double>(pages) * pageSize : 1e18;
  }
  for (const double headroom : { CgroupHeadroom(), AddressSpaceHeadroom() })
  {
    if (headroom >= 0.0)
    {
      available = std::min(available, headroom);
    }
  }
  return available;
}

std::string
DescribeBytes(double bytes)
{
  constexpr double   Mebibyte = 1024.0 * 1024.0;
  constexpr double   Gibibyte = 1024.0 * Mebibyte;
  std::ostringstream text;
  const bool         gibibytes = bytes >= Gibibyte;
  const double       value = bytes / (gibibytes ? Gibibyte : Mebibyte);
  // Three significant digits, never an exponent: "0.61 MiB", "2.05 GiB", "26093 GiB".
  if (value >= 1000.0)
  {
    text << std::llround(value);
  }
  else
  {
    text << std::setprecision(3) << value;
  }
  text << (gibibytes ? " GiB" : " MiB");
  // The exact count, in groups of three digits.
  std::string digits = std::to_string(static_cast<unsigned long long>(std::llround(std::max(bytes, 0.0))));
  for (auto k = static_cast<long>(digits.size()) - 3; k > 0; k -= 3)
  {
    digits.insert(static_cast<std::size_t>(k), ",");
  }
  text << " (" << digits << " bytes)";
  return text.str();
}
} // namespace vr
