// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module `elastica`: NumPy arrays in and out, through the application layer that the
// CLI and the MeshLab plugin use (app/filter_run.h, app/reports.h), so a result here equals the
// CLI's on the same input. The GIL is released while the core computes; a progress callback takes
// it back for the call. Nothing partial comes back: a failure raises elastica.Error (or a
// subclass) and no array is returned.
#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/app/filter_spec.h>
#include <elastica/app/reports.h>
#include <elastica/errors.h>
#include <elastica/face_set.h>
#include <elastica/geometry.h>
#include <elastica/io/atomic_file.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <map>
#include <stdexcept>
#include <optional>
#include <string>

namespace py = pybind11;
using namespace elastica;

namespace {

// ---- arrays -> TriMesh, checked as the CLI's readers check a file ------------------------------

TriMesh toMesh(const py::handle& vertices, const py::handle& faces) {
  // Any real dtype for V (converted to float64), any integer dtype for F.
  py::array vArr = py::array::ensure(vertices);
  py::array fArr = py::array::ensure(faces);
  if (!vArr || !fArr) throw InvalidInputError("V and F must be array-like");
  const auto vKind = vArr.dtype().kind(), fKind = fArr.dtype().kind();
  if (vKind != 'f' && vKind != 'i' && vKind != 'u') throw InvalidInputError("V must hold real numbers");
  if (fKind != 'i' && fKind != 'u') throw InvalidInputError("F must hold integers (vertex indices)");
  const auto V = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vArr);
  const auto F = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(fArr);
  if (V.ndim() != 2 || V.shape(1) != 3)
    throw InvalidInputError("V must have shape (n, 3), not " + py::str(py::tuple(vArr.attr("shape"))).cast<std::string>());
  if (F.ndim() != 2 || F.shape(1) != 3)
    throw InvalidInputError("F must have shape (m, 3) (triangles), not " +
                            py::str(py::tuple(fArr.attr("shape"))).cast<std::string>());
  TriMesh mesh;
  const auto n = V.shape(0), m = F.shape(0);
  mesh.positions.resize(static_cast<std::size_t>(n));
  const double* v = V.data();
  for (py::ssize_t i = 0; i < n; ++i) {
    const Vec3 p(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    if (!p.allFinite()) throw InvalidInputError("V[" + std::to_string(i) + "] is not finite");
    mesh.positions[static_cast<std::size_t>(i)] = p;
  }
  mesh.faces.resize(static_cast<std::size_t>(m));
  const long long* f = F.data();
  for (py::ssize_t i = 0; i < m; ++i)
    for (int k = 0; k < 3; ++k) {
      const long long idx = f[3 * i + k];
      if (idx < 0 || idx >= n)
        throw InvalidInputError("F[" + std::to_string(i) + "] refers to vertex " + std::to_string(idx) + " of " +
                                std::to_string(n));
      mesh.faces[static_cast<std::size_t>(i)][k] = static_cast<int>(idx);
    }
  return mesh;
}

py::array_t<double> vertexArray(const TriMesh& mesh) {
  py::array_t<double> V({static_cast<py::ssize_t>(mesh.vertexCount()), py::ssize_t(3)});
  auto out = V.mutable_unchecked<2>();
  for (int i = 0; i < mesh.vertexCount(); ++i)
    for (int k = 0; k < 3; ++k) out(i, k) = mesh.positions[static_cast<std::size_t>(i)][k];
  return V;
}

py::array_t<std::int32_t> faceArray(const TriMesh& mesh) {
  py::array_t<std::int32_t> F({static_cast<py::ssize_t>(mesh.faceCount()), py::ssize_t(3)});
  auto out = F.mutable_unchecked<2>();
  for (int i = 0; i < mesh.faceCount(); ++i)
    for (int k = 0; k < 3; ++k) out(i, k) = mesh.faces[static_cast<std::size_t>(i)][k];
  return F;
}

py::array_t<double> doubleArray(const std::vector<double>& x) {
  py::array_t<double> a(static_cast<py::ssize_t>(x.size()));
  std::copy(x.begin(), x.end(), a.mutable_data());
  return a;
}

py::object toPython(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

// A choice by its CLI word ("semi-implicit"), with the CLI's words listed on error.
template <class E>
E choice(const std::string& what, const std::string& name) {
  for (const app::Choice<E>& c : app::choices<E>())
    if (name == c.name) return c.value;
  std::string known;
  for (const app::Choice<E>& c : app::choices<E>()) known += std::string(known.empty() ? "" : ", ") + c.name;
  throw InvalidInputError(what + " must be one of " + known + ", not '" + name + "'");
}

// The region selected_faces names: face indices, or a bool mask per face.
std::optional<FaceSet> selectionFrom(const py::object& selected, int faceCount) {
  if (selected.is_none()) return std::nullopt;
  py::array a = py::array::ensure(selected);
  if (!a) throw InvalidInputError("selected_faces must be face indices or a bool mask");
  FaceSet region({});
  if (a.dtype().kind() == 'b') {
    const auto mask = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a);
    if (mask.ndim() != 1 || mask.shape(0) != faceCount)
      throw InvalidInputError("a bool selected_faces needs one entry per face (" + std::to_string(faceCount) + ")");
    for (int f = 0; f < faceCount; ++f)
      if (mask.data()[f]) region.faces.push_back(f);
  } else {
    const auto idx = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!idx || idx.ndim() != 1) throw InvalidInputError("selected_faces must be a 1-D array of face indices");
    for (py::ssize_t i = 0; i < idx.shape(0); ++i) {
      const long long f = idx.data()[i];
      if (f < 0 || f >= faceCount)
        throw InvalidInputError("selected_faces: " + std::to_string(f) + " is not a face of " + std::to_string(faceCount));
      region.faces.push_back(static_cast<int>(f));
    }
  }
  if (region.faces.empty()) throw InvalidInputError("selected_faces selects no face");
  return region;
}

// progress(dict) -> bool on the flow's checks, with the GIL held for the call. A Python exception
// in the callback cancels the run and is raised once the core has unwound. Every check also runs
// Python's signal handlers, with or without a callback: Ctrl-C (SIGINT) raises KeyboardInterrupt
// from its handler, which cancels the run the same way, and the input arrays are never written.
struct PythonProgress {
  py::object callback;
  std::exception_ptr error;
  bool cancelled = false;  ///< the callback returned False (or raised), or a signal handler raised

  std::function<bool(const FlowProgress&)> hook() {
    return [this](const FlowProgress& p) {
      py::gil_scoped_acquire gil;
      try {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (callback.is_none()) return true;
        py::dict d;
        d["level"] = p.level;
        d["step"] = p.step;
        d["energy"] = p.energy;
        d["lambda"] = p.lambda;
        d["seconds"] = p.seconds;
        const py::object r = callback(d);
        cancelled = !(r.is_none() || r.cast<bool>());
        return !cancelled;
      } catch (...) {
        error = std::current_exception();
        cancelled = true;
        return false;
      }
    };
  }
  void rethrow() {
    if (error) std::rethrow_exception(error);
  }
};

// Runs `job` without the GIL; Python errors from the progress callback come first.
template <class Job>
auto withoutGil(PythonProgress& progress, Job job) {
  std::optional<decltype(job())> result;
  std::exception_ptr failure;
  {
    py::gil_scoped_release release;
    try {
      result.emplace(job());
    } catch (...) {
      failure = std::current_exception();
    }
  }
  progress.rethrow();
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

// ---- keyword arguments, by the options table (app/filter_spec.h) --------------------------------

const char* typeWord(app::ParamType t) {
  switch (t) {
    case app::ParamType::Bool: return "a bool";
    case app::ParamType::Int: return "an int";
    case app::ParamType::Enum: return "a str";
    case app::ParamType::Float:
    case app::ParamType::AbsPerc: break;
  }
  return "a number";
}

// The value of keyword `p` as the table stores it (an enum's index; None: not given).
double keywordValue(const app::ParamSpec& p, const py::handle& value) {
  try {
    switch (p.type) {
      case app::ParamType::Bool: return value.cast<bool>() ? 1 : 0;
      case app::ParamType::Int: return double(value.cast<long long>());
      case app::ParamType::Float:
      case app::ParamType::AbsPerc: return value.cast<double>();
      case app::ParamType::Enum: {
        const std::string word = value.cast<std::string>();
        std::string known;
        for (std::size_t i = 0; i < p.enumWords.size(); ++i) {
          if (p.enumWords[i] == word) return double(i);
          known += (i ? ", " : "") + p.enumWords[i];
        }
        throw InvalidInputError(p.keyword + " must be one of " + known + ", not '" + word + "'");
      }
    }
  } catch (const py::cast_error&) {
  }
  throw py::type_error(p.keyword + " must be " + typeWord(p.type) + ", not " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

// The keyword arguments of `function` (a filter's rows with a keyword, plus the face's own
// `extra`), each checked against its row's type and range with the error in the caller's words.
app::ParamValues keywordValues(const char* function, const app::FilterSpec& spec, const py::kwargs& kwargs,
                               std::initializer_list<const char*> extra) {
  app::ParamValues values;
  for (const auto& [k, value] : kwargs) {
    const std::string key = k.cast<std::string>();
    const app::ParamSpec* row = nullptr;
    for (const app::ParamSpec& p : spec.params)
      if (p.keyword == key) row = &p;
    if (!row) {
      if (std::find(extra.begin(), extra.end(), key) != extra.end()) continue;
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + key + "'");
    }
    if (value.is_none()) continue;  // the default
    const double x = keywordValue(*row, value);
    app::checkValue(*row, x, app::Caller::Python);
    values.set(row->key(), x);
  }
  return values;
}

py::object extraKeyword(const py::kwargs& kwargs, const char* name) {
  return kwargs.contains(name) ? py::reinterpret_borrow<py::object>(kwargs[name]) : py::object(py::none());
}

// A MeshLab float (stored as float, widened: 0.05 is 0.05000000074505806) as the decimal it was
// typed as: the shortest one that is the same float.
double typedDecimal(double widened) {
  const float f = static_cast<float>(widened);
  for (int digits = 1; digits <= 9; ++digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, widened);
    const double d = std::strtod(text, nullptr);
    if (static_cast<float>(d) == f) return d;
  }
  return widened;
}

// A keyword's default as Python writes it: the core's (the CLI's and this module's start).
std::string pythonDefault(const app::ParamSpec& p) {
  const double x = p.get(app::JobOptions{});
  if (p.type == app::ParamType::AbsPerc && x == app::kAutoFeatureSize) return "None";  // auto (fairing_amount.h)
  switch (p.type) {
    case app::ParamType::Bool: return x != 0 ? "True" : "False";
    case app::ParamType::Enum: return "'" + p.enumWords.at(static_cast<std::size_t>(x)) + "'";
    case app::ParamType::Int: return std::to_string(static_cast<long long>(x));
    case app::ParamType::Float:
    case app::ParamType::AbsPerc: break;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

// "fair(V, F, selected_faces=None, *, flow='elastica', ...) -> ..." from the table.
std::string signature(const char* function, const char* positional, app::FilterId id, const char* extra,
                      const char* returns) {
  std::string s = std::string(function) + "(" + positional + ", *";
  for (const app::ParamSpec& p : app::filterSpec(id, {}).params)
    if (!p.keyword.empty()) s += ", " + p.keyword + "=" + pythonDefault(p);
  return s + extra + ") -> " + returns + "\n\n";
}

// ---- the functions --------------------------------------------------------------------------

py::tuple fairArrays(const py::object& V, const py::object& F, const py::object& selectedFaces, const py::kwargs& kwargs) {
  const app::FilterSpec spec = app::filterSpec(app::FilterId::Fairing, {});
  const app::ParamValues values = keywordValues("fair", spec, kwargs, {"progress"});
  TriMesh mesh = toMesh(V, F);
  std::optional<FaceSet> region = selectionFrom(selectedFaces, mesh.faceCount());
  FlowOptions opt = app::readJob(spec, values, app::Caller::Python).flow;
  PythonProgress hook{extraKeyword(kwargs, "progress"), nullptr};
  opt.progress = hook.hook();
  const int inV = mesh.vertexCount(), inF = mesh.faceCount();
  app::FairingResult r = withoutGil(hook, [&] {
    return app::runFairing(std::move(mesh), std::move(region), opt, /*outputCurvature=*/false);
  });
  return py::make_tuple(vertexArray(r.mesh), faceArray(r.mesh),
                        toPython(app::fairingReport(r.report, opt, inV, inF, &r)));
}

double autoFeatureSizeArrays(const py::object& V, const py::object& F, const py::object& selectedFaces) {
  const TriMesh mesh = toMesh(V, F);
  const std::optional<FaceSet> region = selectionFrom(selectedFaces, mesh.faceCount());
  return app::autoFeatureSize(mesh, region ? &*region : nullptr);
}

double roughnessArrays(const py::object& V, const py::object& F, const py::object& selectedFaces) {
  const TriMesh mesh = toMesh(V, F);
  const std::optional<FaceSet> region = selectionFrom(selectedFaces, mesh.faceCount());
  return app::surfaceRoughness(mesh, region ? &*region : nullptr);
}

py::tuple fillArrays(const py::object& V, const py::object& F, const py::kwargs& kwargs) {
  const app::FilterSpec spec = app::filterSpec(app::FilterId::FillHoles, {});
  const app::ParamValues values = keywordValues("fill_holes", spec, kwargs, {"progress"});
  TriMesh mesh = toMesh(V, F);
  app::checkFillInput(mesh, app::RepairHints::None);
  HoleFillOptions opt = app::readJob(spec, values, app::Caller::Python).fill;
  PythonProgress hook{extraKeyword(kwargs, "progress"), nullptr};
  opt.flow.progress = hook.hook();
  app::FillHolesResult r = withoutGil(hook, [&] { return app::runFillHoles(std::move(mesh), opt); });
  // fillHoles stops at the hole it was cancelled in: give back nothing rather than a part.
  if (hook.cancelled) throw Error("cancelled; nothing filled");
  py::array_t<bool> isNew(static_cast<py::ssize_t>(r.mesh.faceCount()));
  for (int f = 0; f < r.mesh.faceCount(); ++f) isNew.mutable_data()[f] = r.report.isNewFace(f);
  return py::make_tuple(vertexArray(r.mesh), faceArray(r.mesh), isNew, toPython(app::fillingReport(r, opt)));
}

py::dict curvatureArrays(const py::object& V, const py::object& F, const py::kwargs& kwargs) {
  const app::FilterSpec spec = app::filterSpec(app::FilterId::Curvature, {});
  const app::ParamValues values = keywordValues("curvature", spec, kwargs, {});
  const TriMesh mesh = toMesh(V, F);
  app::checkedTopology(mesh, /*rejectNonManifoldVertices=*/false, app::RepairHints::None);
  const CurvatureMeasureOptions opt = app::readJob(spec, values, app::Caller::Python).curvature;
  PythonProgress none{py::none(), nullptr};
  const app::CurvatureResult r = withoutGil(none, [&] { return app::runCurvature(mesh, opt); });
  py::dict d;
  d["H"] = doubleArray(r.outputH());
  d["K"] = doubleArray(r.curvature.K);
  d["energy"] = r.curvature.energy;
  return d;
}

// A str or os.PathLike (pathlib.Path) as a file name.
std::string pathOf(const py::object& path) { return py::module_::import("os").attr("fspath")(path).cast<std::string>(); }

py::tuple readFile(const py::object& pathLike, bool selection) {
  const std::string path = pathOf(pathLike);
  const io::MeshFile file = io::readMesh(path);  // the CLI's reader: its checks, repairs and messages
  const TriMesh& mesh = file.mesh;
  if (!selection) return py::make_tuple(vertexArray(mesh), faceArray(mesh));
  // MeshLab's face selection (PLY face flags); no flags in the file: nothing selected.
  py::array_t<bool> selected(static_cast<py::ssize_t>(mesh.faceCount()));
  for (int f = 0; f < mesh.faceCount(); ++f)
    selected.mutable_data()[f] = file.report.hasFaceSelection && file.faceSelection[static_cast<std::size_t>(f)] != 0;
  return py::make_tuple(vertexArray(mesh), faceArray(mesh), selected);
}

void writeFile(const py::object& pathLike, const py::object& V, const py::object& F, bool ascii,
               const py::object& selectedFaces) {
  const std::string path = pathOf(pathLike);
  const TriMesh mesh = toMesh(V, F);
  io::PlyAttributes attributes;
  std::vector<int> flags;
  if (!selectedFaces.is_none()) {
    if (io::formatFromExtension(path) != io::MeshFormat::Ply)
      throw InvalidInputError("selected_faces: only a .ply file stores a face selection, not " + path);
    flags.assign(static_cast<std::size_t>(mesh.faceCount()), 0);
    // No face selected (an all-False mask, no indices) is a selection too, as MeshLab saves one.
    const py::array given = py::array::ensure(selectedFaces);
    const bool none = given && (given.size() == 0 || (given.dtype().kind() == 'b' && !py::bool_(given.attr("any")())));
    if (none && given.dtype().kind() == 'b' && given.size() != mesh.faceCount())
      throw InvalidInputError("a bool selected_faces needs one entry per face (" + std::to_string(mesh.faceCount()) + ")");
    if (!none) {
      const std::optional<FaceSet> region = selectionFrom(selectedFaces, mesh.faceCount());
      for (int f : region->faces) flags[static_cast<std::size_t>(f)] = io::kPlyFaceSelected;
    }
    attributes.faceFlags = &flags;
  }
  io::writeMesh(path, mesh, attributes, !ascii);  // by extension; atomic: a failed write leaves no half-written file
}

// ---- the options table, for faces that build dialogs (the Blender add-on) ----------------------

py::dict filterSpecs() {
  static const std::map<app::FilterId, const char*> function = {
      {app::FilterId::Fairing, "fair"}, {app::FilterId::FillHoles, "fill_holes"}, {app::FilterId::Curvature, "curvature"}};
  py::dict all;
  for (const app::FilterSpec& f : app::allFilters({})) {
    py::list params;
    auto orNone = [](const std::string& s) { return s.empty() ? py::object(py::none()) : py::object(py::str(s)); };
    for (const app::ParamSpec& p : f.params) {
      py::dict d;
      d["name"] = orNone(p.name);
      d["field"] = p.field;
      d["keyword"] = orNone(p.keyword);
      d["blender"] = orNone(p.blenderProperty);
      d["cli"] = orNone(p.cliFlag);
      d["label"] = p.label;
      d["description"] = p.tooltip;
      d["rich_type"] = app::richTypeName(p.type);  // the .mlx type
      switch (p.type) {
        case app::ParamType::Bool:
          d["type"] = "bool";
          d["default"] = p.defaultValue != 0;
          break;
        case app::ParamType::Int:
          d["type"] = "int";
          d["default"] = static_cast<long long>(p.defaultValue);
          break;
        case app::ParamType::Float:  // MeshLab's are floats: shown as typed
          d["type"] = "float";
          d["default"] = p.inMeshLab() ? typedDecimal(p.defaultValue) : p.defaultValue;
          break;
        case app::ParamType::AbsPerc:  // a length in the mesh's units, as on every face
          d["type"] = "float";
          d["unit"] = "length";
          // None: sized from the mesh at hand (auto_feature_size), as the MeshLab dialog does.
          d["default"] = p.get(app::JobOptions{}) == app::kAutoFeatureSize ? py::object(py::none())
                                                                            : py::object(py::float_(typedDecimal(p.defaultValue)));
          break;
        case app::ParamType::Enum:
          d["type"] = "enum";
          d["choices"] = p.enumWords;
          d["labels"] = p.enumValues;
          d["default"] = p.enumWords.at(static_cast<std::size_t>(p.defaultValue));
          break;
      }
      auto bound = [](double x) { return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none()); };
      if (p.type == app::ParamType::Int || p.type == app::ParamType::Float) {
        d["min"] = bound(p.minValue);  // with min_exclusive, the minimum itself is refused
        d["max"] = bound(p.maxValue);
        d["min_exclusive"] = p.minExclusive;
      }
      if (p.type == app::ParamType::AbsPerc) {
        d["min"] = 0.0;
        d["max"] = py::none();
      }
      params.append(d);
    }
    py::dict spec;
    spec["name"] = f.name;
    spec["info"] = f.info;
    spec["parameters"] = params;
    all[function.at(f.id)] = spec;
  }
  return all;
}

}  // namespace

PYBIND11_MODULE(elastica, m) {
  py::options options;
  options.disable_function_signatures();  // each docstring starts with the Python signature
  m.doc() =
      "Fair triangle meshes with the discrete elastica flow (Yoshizawa & Belyaev 2002): fair, fill_holes,\n"
      "curvature, read, write. Meshes are NumPy arrays: V (n, 3) float64 positions, F (m, 3) int triangles.\n"
      "Errors raise elastica.Error: InvalidInputError (also a ValueError) for bad arrays, options or meshes,\n"
      "NumericalError (a RuntimeError) when a flow diverges, IoError (an OSError) for files.";

  // The exception hierarchy: elastica.Error, and subclasses that are also the builtin that fits.
  static py::object error = py::reinterpret_steal<py::object>(
      PyErr_NewExceptionWithDoc("elastica.Error", "Base class of every error elastica raises.", PyExc_Exception, nullptr));
  auto subclass = [&](const char* name, PyObject* builtin, const char* doc) {
    py::tuple bases = py::make_tuple(error, py::handle(builtin));
    return py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(name, doc, bases.ptr(), nullptr));
  };
  static py::object invalid = subclass("elastica.InvalidInputError", PyExc_ValueError, "Bad arrays, options or mesh.");
  static py::object numerical = subclass("elastica.NumericalError", PyExc_RuntimeError, "A flow diverged.");
  static py::object ioError = subclass("elastica.IoError", PyExc_OSError, "A file could not be read or written.");
  m.attr("Error") = error;
  m.attr("InvalidInputError") = invalid;
  m.attr("NumericalError") = numerical;
  m.attr("IoError") = ioError;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInputError& e) {
      PyErr_SetString(invalid.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical.ptr(), e.what());
    } catch (const IoError& e) {
      PyErr_SetString(ioError.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });

  // The keyword arguments, their defaults (the core's) and the signatures below come from the
  // options table (app/filter_spec.h); an unknown keyword raises TypeError, None takes the default.
  m.def("fair", &fairArrays, py::arg("V"), py::arg("F"), py::arg("selected_faces") = py::none(),
        (signature("fair", "V, F, selected_faces=None", app::FilterId::Fairing, ", progress=None",
                   "(V_out, F_out, report)") +
         "Fairs the mesh with a curvature flow, as `elastica fair`: flow 'elastica' (F = -Lap H - 2H(H^2-K)),\n"
         "'lmc' or 'bilaplacian'; scheme 'explicit', 'semi-implicit', 'vector' or 'auto';\n"
         "subdivide: coarse-to-fine 1-to-4 subdivisions (0..8); max_steps and max_seconds 0: no limit;\n"
         "feature_size: a fairing amount, a length in the mesh's units, as report['feature_size'] holds it (bumps\n"
         "smaller than it are smoothed away, larger shapes kept; report['stop'] 'feature_size'); None (the\n"
         "default): sized from the faces to fair by their edge lengths and roughness (auto_feature_size), halved\n"
         "while it would raise the energy; report['rough'] says when the result is still rough, with\n"
         "report['suggested_feature_size']; 0: fair\n"
         "until converged, to the limit shape (a sphere, a Clifford torus);\n"
         "boundary 'fixed' (boundary and next row clamped) or 'slide'. remesh (not explicit): the\n"
         "mesh-quality stages (pre-subdivision, isotropic remeshing of the moving region, edge flips, embedding\n"
         "guard), so F_out may differ from F; False keeps the connectivity (`--no-remesh`). flip_edges: flip\n"
         "non-Delaunay edges at every check (`--flip-edges`). A keyword given as None takes its default.\n"
         "selected_faces: face indices or a bool mask; only vertices whose faces are all selected move.\n"
         "progress(dict) -> bool is called at every check with level, step, energy, lambda, seconds; return\n"
         "False to cancel (raises elastica.Error). report: the dict `elastica fair --report` writes (without\n"
         "file names).")
            .c_str());
  m.def("auto_feature_size", &autoFeatureSizeArrays, py::arg("V"), py::arg("F"), py::arg("selected_faces") = py::none(),
        "auto_feature_size(V, F, selected_faces=None) -> float\n\n"
        "The fairing amount fair() takes by default (feature_size=None), a length in the mesh's units: the 25 %\n"
        "quantile of the edge lengths of the faces to fair (the selected ones, else all) times 2 on a clean\n"
        "surface, more on a rough one; on one rougher than 0.045 without long slivers, 2.2 + 6 (roughness - 0.1)\n"
        "mean edges, run with uniform operators and twiced (report['amount_operators']). What the MeshLab dialog and Blender's redo panel show as the default\n"
        "feature size, and report['feature_size'] of a default fair() (unless report['feature_size_halvings']).");
  m.def("surface_roughness", &roughnessArrays, py::arg("V"), py::arg("F"), py::arg("selected_faces") = py::none(),
        "surface_roughness(V, F, selected_faces=None) -> float\n\n"
        "How rough the faces to fair are, as the default amount measures it (report['roughness_before']): the\n"
        "median over their vertices of the height over the neighbours' centre along the normal, less the\n"
        "neighbours' mean height, in median edge lengths. Curvature cancels; vertex noise does not.");
  m.def("fill_holes", &fillArrays, py::arg("V"), py::arg("F"),
        (signature("fill_holes", "V, F", app::FilterId::FillHoles, ", progress=None",
                   "(V_out, F_out, new_faces, report)") +
         "Fills every hole with at most max_hole_edges border edges, as `elastica fill`; an open surface's outer\n"
         "rim stays open unless close_rims (report['holes'][i]['rim'] tells which loops are rims). The input's\n"
         "vertices and faces come first, unchanged, and new_faces is True on the appended patch faces. max_steps\n"
         "bounds the whole fill (the holes' flows share it). A keyword given as None takes its default.\n"
         "report: the dict `elastica fill --report` writes (without file names).")
            .c_str());
  m.def("curvature", &curvatureArrays, py::arg("V"), py::arg("F"),
        (signature("curvature", "V, F", app::FilterId::Curvature, "", "{'H': array, 'K': array, 'energy': float}") +
         "Per-vertex mean curvature H (+1/r on a sphere with outward normals; H/lambda where the paper's lambda\n"
         "fix applies), angle-deficit Gaussian curvature K, and the total curvature energy E = sum (4H^2 - 2K) A,\n"
         "as `elastica curvature`. area: 'mixed' (Meyer et al.) or 'barycentric' (the paper's A/3).")
            .c_str());
  m.def("read", &readFile, py::arg("path"), py::kw_only(), py::arg("selection") = false,
        "read(path, *, selection=False) -> (V, F), or (V, F, selected) with selection\n\nReads PLY, OFF, STL or OBJ\n"
        "with the `elastica` command's reader: polygons split, STL corners merged, degenerate and duplicate faces\n"
        "removed, bow-tie vertices split; a malformed file raises elastica.IoError naming what and where. With\n"
        "selection, also a bool mask per face: MeshLab's face selection (a PLY's face flags; all False without).");
  m.def("write", &writeFile, py::arg("path"), py::arg("V"), py::arg("F"), py::kw_only(), py::arg("ascii") = false,
        py::arg("selected_faces") = py::none(),
        "write(path, V, F, *, ascii=False, selected_faces=None)\n\nWrites the format the extension names (.ply,\n"
        ".off, .obj, .stl; PLY and STL binary unless ascii) atomically: on failure the destination is left as it\n"
        "was; an unknown extension raises elastica.IoError. selected_faces (a bool mask per face or face indices,\n"
        "e.g. fill_holes' new_faces) is stored as MeshLab's face selection (PLY face flags); .ply only.");
  m.def("filters", &filterSpecs,
        "filters() -> {'fair': spec, 'fill_holes': spec, 'curvature': spec}\n\n"
        "The options table, for a face that builds a dialog (the Blender add-on): each spec has the filter's\n"
        "'name' and 'info' (HTML) and 'parameters', one dict per row: 'name' (the .mlx name, None where MeshLab\n"
        "has no such parameter), 'field' (the C++ options field), 'keyword' (this module's keyword argument, or\n"
        "None where the caller decides: the selection, colouring, selecting new faces), 'blender' (the Blender\n"
        "property, or None), 'cli' (the command-line flag, or None), 'type' ('bool', 'int', 'float', 'enum'),\n"
        "'default' (the dialogs'), 'label', 'description', for numbers 'min' and 'max' (None: unbounded), for\n"
        "enums 'choices' (keyword values) and 'labels' (menu). Passing every keyword of the MeshLab parameters at\n"
        "its default runs what the MeshLab filter runs at its defaults.");
}
