// SPDX-License-Identifier: GPL-3.0-or-later
#include "readers.h"

#include <cerrno>
#include <cstdlib>

namespace elastica::io::detail {

std::vector<std::string_view> splitTokens(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; };
  while (i < line.size()) {
    while (i < line.size() && space(line[i])) ++i;
    const size_t start = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool parseNumber(std::string_view token, double& value) {
  if (token.empty() || token.size() > 64) return false;
  const std::string s(token);  // strtod needs a terminated string
  char* end = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

bool parseInteger(std::string_view token, long long& value) {
  if (token.empty() || token.size() > 24) return false;
  const std::string s(token);
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(s.c_str(), &end, 10);
  return end == s.c_str() + s.size() && errno == 0;
}

std::string quote(std::string_view s, std::size_t n) {
  std::string out = "'";
  for (char c : s.substr(0, n)) out += (c >= 32 && c < 127) ? c : '?';
  return out + (s.size() > n ? "...'" : "'");
}

}  // namespace elastica::io::detail
