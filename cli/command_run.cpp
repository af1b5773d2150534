// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica run -i IN -o OUT -s SCRIPT.mlx`: run a MeshLab filter script that uses the Elastica
// filters, as meshlabserver with the plugin would, with the same parameter semantics and the same
// numerics (both go through app/). Friendlier than meshlabserver: a parameter the script omits
// takes its default, with a warning.
#include "commands.h"
#include "mesh_command.h"
#include "mesh_files.h"
#include "mlx_script.h"

#include <elastica/errors.h>
#include <elastica/app/filter_apply.h>
#include <elastica/app/filter_spec.h>
#include <elastica/vcg_mesh.h>

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>

namespace elastica::cli {
namespace {

namespace ea = app;

struct RunArgs {
  std::string input, output, script;
  bool ascii = false;
};

// Parses a script value the way MeshLab reads it into the parameter's type (RichFloat is a float).
// Returns false if `text` is not a value of that type.
bool parseValue(ea::ParamType type, const std::string& text, double& out) {
  if (type == ea::ParamType::Bool) {
    std::string lower;
    for (char c : text) lower += char(std::tolower(static_cast<unsigned char>(c)));
    if (lower != "true" && lower != "false") return false;
    out = lower == "true" ? 1 : 0;
    return true;
  }
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  if (type == ea::ParamType::Float || type == ea::ParamType::AbsPerc) {
    const float f = std::strtof(text.c_str(), &end);
    out = f;
    return *end == '\0' && errno == 0 && std::isfinite(f);
  }
  const long i = std::strtol(text.c_str(), &end, 10);
  out = double(i);
  return *end == '\0' && errno == 0 && i >= INT32_MIN && i <= INT32_MAX;
}

std::string knownFilters() {
  std::string names;
  for (const ea::FilterSpec& s : ea::allFilters({})) names += (names.empty() ? "'" : ", '") + s.name + "'";
  return names;
}

// Checks the whole script before any work: every filter one of ours, every parameter known,
// of the right type and value, none twice. Unknown filters and parameters are errors.
void checkScript(const std::string& path, const std::vector<MlxFilter>& script) {
  if (script.empty()) throw InvalidInputError(path + ": the script has no <filter>");
  for (const MlxFilter& f : script) {
    const std::string where = path + ":" + std::to_string(f.line) + ": ";
    const auto id = ea::findFilter(f.name);
    if (!id)
      throw InvalidInputError(where + "unknown filter '" + f.name + "' (elastica run knows " + knownFilters() + ")");
    const ea::FilterSpec spec = ea::filterSpec(*id, {});
    std::set<std::string> seen;
    for (const MlxParam& p : f.params) {
      const std::string at = path + ":" + std::to_string(p.line) + ": filter '" + f.name + "': parameter '" + p.name + "'";
      const ea::ParamSpec* ps = spec.param(p.name);
      if (!ps) throw InvalidInputError(at + " is not one of its parameters");
      if (!seen.insert(p.name).second) throw InvalidInputError(at + " is given twice");
      if (p.type != ea::richTypeName(ps->type))
        throw InvalidInputError(at + " is a " + ea::richTypeName(ps->type) + ", not a " + p.type);
      double v;
      if (!parseValue(ps->type, p.value, v))
        throw InvalidInputError(at + ": '" + p.value + "' is not a " + ea::richTypeName(ps->type) + " value");
    }
  }
}

std::string describeDefault(const ea::ParamSpec& p) {
  if (p.type == ea::ParamType::Bool) return p.defaultValue != 0 ? "true" : "false";
  if (p.type == ea::ParamType::Enum) return std::to_string(int(p.defaultValue)) + " (" + p.enumValues[int(p.defaultValue)] + ")";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", p.defaultValue);
  return buf;
}

// The values of one script filter on the current mesh: defaults (which may depend on the mesh,
// as in MeshLab's dialog), overridden by the script.
ea::ParamValues resolveValues(const std::string& path, const MlxFilter& f, const ea::FilterSpec& spec) {
  ea::ParamValues values = ea::ParamValues::defaults(spec);
  for (const ea::ParamSpec& ps : spec.params) {
    if (!ps.inMeshLab()) continue;
    const MlxParam* given = nullptr;
    for (const MlxParam& p : f.params)
      if (p.name == ps.name) given = &p;
    if (!given) {
      std::cerr << "warning: " << path << ":" << f.line << ": filter '" << f.name << "' does not set '" << ps.name
                << "'; using its default " << describeDefault(ps) << " (meshlabserver would abort)\n";
      continue;
    }
    double v = 0;
    parseValue(ps.type, given->value, v);  // checked by checkScript
    values.set(ps.name, v);
  }
  return values;
}

void runScript(const RunArgs& a) {
  checkMeshOutput(a.output, a.input);
  const std::vector<MlxFilter> script = readMlxScript(a.script);
  checkScript(a.script, script);

  VcgMesh vm;
  const io::ReadReport read = loadMesh(a.input, vm);
  io::PlyWriteOptions w;
  w.binary = !a.ascii;
  w.faceFlags = read.hasFaceSelection;
  const bool tty = isatty(STDERR_FILENO);
  for (const MlxFilter& f : script) {
    const ea::FilterId id = *ea::findFilter(f.name);
    const ea::FilterSpec spec = ea::filterSpec(id, ea::meshFacts(vm));
    const ea::ParamValues values = resolveValues(a.script, f, spec);
    bool drawn = false;
    ea::Progress progress = [&](int, const std::string& what) {
      if (tty) std::fprintf(stderr, "\r%s   ", what.c_str());
      drawn = tty;
      return true;
    };
    std::vector<ea::LogLine> summary;
    try {
      summary = ea::applyFilter(id, vm, values, progress).log;
    } catch (const Error& e) {
      if (drawn) std::fprintf(stderr, "\n");
      throw Error(a.script + ":" + std::to_string(f.line) + ": " + f.name + ": " + e.what() + "; nothing written");
    }
    if (drawn) std::fprintf(stderr, "\n");
    for (const ea::LogLine& line : summary)
      std::printf("%s: %s%s\n", f.name.c_str(), line.severity == ea::Severity::Warning ? "warning: " : "",
                  line.text.c_str());
    const ea::FilterOutputs outputs = ea::filterOutputs(id, ea::readJob(spec, values, ea::Caller::MeshLab));
    if (outputs.curvature) w.vertexQuality = w.vertexColor = w.curvature = true;
    if (outputs.faceSelection) w.faceFlags = true;
  }
  writeMeshFile(a.output, vm, w);
  std::printf("wrote %s (%s, %s)\n", a.output.c_str(), plural(vm.vn, "vertex").c_str(), plural(vm.fn, "face").c_str());
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = addMeshCommand(app, "run", args->input, args->output,
      "Run a MeshLab filter script (.mlx) that uses the Elastica filters ('Discrete Elastica Fairing',\n"
      "'Fill Holes with Discrete Elastica', 'Discrete Elastica Curvature'), as meshlabserver with the\n"
      "Elastica plugin would. Parameters the script omits take their defaults (with a warning).\n"
      "Writes the mesh in the format of -o's extension.", "-i,--input");
  cmd->add_option("-s,--script", args->script, "MeshLab filter script (.mlx)")->required();
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->callback([args] { runScript(*args); });
}

}  // namespace elastica::cli
