// The bodies of chapters/cache_sizes.h's functions (the data caches /sys describes), compiled once.
#include "cache_sizes.h"

namespace ch {

std::uint64_t parseCacheSize(const std::string& text) {
  std::size_t i = 0;
  std::uint64_t v = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
    if (v > (std::uint64_t(1) << 40)) return 0;
    v = 10 * v + std::uint64_t(text[i++] - '0');
  }
  if (i == 0) return 0;
  std::uint64_t unit = 1;
  if (i < text.size() && (text[i] == 'K' || text[i] == 'M' || text[i] == 'G')) {
    unit = text[i] == 'K' ? 1024 : text[i] == 'M' ? 1024 * 1024 : 1024 * 1024 * 1024;
    ++i;
  }
  while (i < text.size() && (text[i] == '\n' || text[i] == ' ' || text[i] == '\r')) ++i;
  return i == text.size() ? v * unit : 0;
}

std::string cacheSizeText(std::uint64_t bytes) {
  const std::uint64_t mib = 1024 * 1024;
  if (bytes >= mib && bytes % mib == 0) return std::to_string(bytes / mib) + " MiB";
  if (bytes % 1024 == 0) return std::to_string(bytes / 1024) + " KiB";
  return std::to_string(bytes) + " B";
}

std::vector<CacheSize> dataCaches(const std::filesystem::path& dir) {
  std::vector<CacheSize> out;
  std::error_code ec;
  std::vector<std::filesystem::path> entries;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind("index", 0) == 0) entries.push_back(it->path());
  std::sort(entries.begin(), entries.end());
  auto word = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    std::string w;
    in >> w;
    return w;
  };
  for (const auto& e : entries) {
    const std::string levelText = word(e / "level"), type = word(e / "type");
    const std::uint64_t bytes = parseCacheSize(word(e / "size"));
    if (levelText.size() != 1 || levelText[0] < '1' || levelText[0] > '9' || bytes == 0) continue;
    if (type != "Data" && type != "Unified") continue;
    const int level = levelText[0] - '0';
    if (std::any_of(out.begin(), out.end(), [&](const CacheSize& c) { return c.level == level; })) continue;
    out.push_back({level, bytes, "L" + std::to_string(level) + (type == "Data" ? "d " : " ") + cacheSizeText(bytes)});
  }
  std::sort(out.begin(), out.end(), [](const CacheSize& a, const CacheSize& b) { return a.level < b.level; });
  return out;
}

}  // namespace ch
