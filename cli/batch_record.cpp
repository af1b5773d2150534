// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_record.h"
#include "flow_report.h"

#include <elastica/errors.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

namespace elastica::cli {
namespace fs = std::filesystem;

namespace {

nlohmann::json recordOf(const RunKey& key, const std::string& inputDigest, const std::string& outputDigest) {
  return {{"program", key.program},
          {"command", key.command},
          {"options", key.options},
          {"input_digest", inputDigest},
          {"output_digest", outputDigest}};
}

}  // namespace

std::string fileDigest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot be read");
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a's offset basis and prime
  std::vector<char> buf(1 << 20);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    const std::streamsize n = in.gcount();
    for (std::streamsize i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(buf[static_cast<std::size_t>(i)])) * 1099511628211ull;
  }
  if (in.bad()) throw IoError(path + ": read error");
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

std::string recordPath(const std::string& output) {
  const fs::path p(output);
  return (p.parent_path() / ".elastica-batch" / (p.filename().string() + ".json")).string();
}

bool isDone(const BatchItem& item, const RunKey& key, const std::string& inputDigest) {
  std::error_code ec;
  if (!fs::is_regular_file(item.output, ec)) return false;
  std::ifstream in(recordPath(item.output));
  if (!in) return false;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.contains("output_digest")) return false;
  try {
    const nlohmann::json want = recordOf(key, inputDigest, fileDigest(item.output));
    for (const auto& [name, value] : want.items())
      if (!j.contains(name) || j[name] != value) return false;
    return true;
  } catch (const IoError&) {
    return false;
  }
}

void writeRecord(const BatchItem& item, const RunKey& key, const std::string& inputDigest) {
  const fs::path dir = fs::path(recordPath(item.output)).parent_path();
  std::error_code ec;
  fs::create_directories(dir, ec);  // shards may race to make it: only its absence below is an error
  if (!fs::is_directory(dir)) throw IoError(dir.string() + ": cannot create the folder of batch records");
  nlohmann::json j = recordOf(key, inputDigest, fileDigest(item.output));
  j["input"] = item.input;  // for a reader; a match needs only the digests
  writeJson(recordPath(item.output), j);
}

}  // namespace elastica::cli
