/// \file cache_sizes.h The data caches of this machine as Linux describes them in
/// /sys/devices/system/cpu/cpu0/cache/index*/ (files `level`, `type`, `size`), for the charts
/// that mark where a kernel's memory outgrows each cache (bench_parallel's time per point).
//
// sysconf(_SC_LEVEL3_CACHE_SIZE) is not used: glibc computes it from CPUID, and on a virtual
// machine it can report what the host has (384 MiB here, where /sys says 32 MiB).
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace ch {

/// One data or unified cache: its level, its size in bytes and a label such as "L1d 48 KiB",
/// "L2 1 MiB".
struct CacheSize {
  int level = 0;
  std::uint64_t bytes = 0;
  std::string label;
};

/// A size as /sys writes it ("48K", "1024K", "32768K", also "32M", "1G" or plain bytes) in
/// bytes; 0 if it is not one.
std::uint64_t parseCacheSize(const std::string& text);

/// `bytes` as the label's size: whole MiB when it is one, else KiB ("48 KiB", "1 MiB").
std::string cacheSizeText(std::uint64_t bytes);

/// The data and unified caches described under `dir` (normally
/// /sys/devices/system/cpu/cpu0/cache): one per level, by increasing level. Instruction caches
/// are left out, and so is an entry whose level, type or size is missing or unreadable. An
/// empty or missing directory gives none: nothing is guessed.
std::vector<CacheSize> dataCaches(const std::filesystem::path& dir);

}  // namespace ch
