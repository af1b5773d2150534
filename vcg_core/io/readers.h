// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces behind readMesh (mesh_reader.cpp), private to elastica_io. Each format reader fills
// the core mesh in file order (vertex i of the file is positions[i]) and throws IoError
// "<path>: <what>" naming the line, vertex or face at fault; checkAndRepair then looks at the mesh
// as a whole. All four formats are parsed here or by tinyobjloader (OBJ), not by vcglib's
// importers, which trust header counts, index without bounds checks and loop on some truncated
// files (see each reader's opening comment).
#pragma once

#include <elastica/io/mesh_reader.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace elastica::io::detail {

[[noreturn]] void fail(const std::string& path, const std::string& what);

void readOff(const std::string& path, TriMesh& mesh, ReadReport& report);
void readStl(const std::string& path, TriMesh& mesh);
void readObj(const std::string& path, TriMesh& mesh, ReadReport& report);

/// Also fills `selection` (one byte per triangle, 1 where the file's face is selected) when the
/// file carries face flags or a "selected" property (report.hasFaceSelection).
void readPly(const std::string& path, std::uintmax_t fileSize, TriMesh& mesh, std::vector<std::uint8_t>& selection,
             ReadReport& report);

/// Whole-mesh checks and safe repairs (see mesh_checks.cpp); records what it repaired. A
/// non-empty `selection` (one byte per face) follows the faces it belongs to.
void checkAndRepair(const std::string& path, TriMesh& mesh, std::vector<std::uint8_t>& selection, ReadReport& report);

// Text helpers for the line-based formats.
std::vector<std::string_view> splitTokens(std::string_view line);
/// A whole token as a number (strtod syntax, so "nan" and "inf" parse: callers check finiteness).
bool parseNumber(std::string_view token, double& value);
/// A whole token as an integer (no sign limits beyond long long).
bool parseInteger(std::string_view token, long long& value);
/// `s` cut to `n` characters, for quoting untrusted text in a message.
std::string quote(std::string_view s, std::size_t n = 20);

}  // namespace elastica::io::detail
