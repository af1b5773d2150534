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
#include <elastica/io/atomic_file.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

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

// The one-byte-per-face selection from selected_faces: face indices, or a bool mask per face.
std::vector<std::uint8_t> selectionFrom(const py::object& selected, int faceCount) {
  std::vector<std::uint8_t> flags;
  if (selected.is_none()) return flags;
  py::array a = py::array::ensure(selected);
  if (!a) throw InvalidInputError("selected_faces must be face indices or a bool mask");
  if (a.dtype().kind() == 'b') {
    const auto mask = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a);
    if (mask.ndim() != 1 || mask.shape(0) != faceCount)
      throw InvalidInputError("a bool selected_faces needs one entry per face (" + std::to_string(faceCount) + ")");
    flags.assign(mask.data(), mask.data() + faceCount);
  } else {
    const auto idx = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!idx || idx.ndim() != 1) throw InvalidInputError("selected_faces must be a 1-D array of face indices");
    std::vector<int> faces;
    for (py::ssize_t i = 0; i < idx.shape(0); ++i) {
      const long long f = idx.data()[i];
      if (f < 0 || f >= faceCount)
        throw InvalidInputError("selected_faces: " + std::to_string(f) + " is not a face of " + std::to_string(faceCount));
      faces.push_back(static_cast<int>(f));
    }
    flags = FaceSet(std::move(faces)).flags(static_cast<std::size_t>(faceCount));
  }
  if (std::count(flags.begin(), flags.end(), 1) == 0) throw InvalidInputError("selected_faces selects no face");
  return flags;
}

// progress(dict) -> bool on the flow's checks, with the GIL held for the call. A Python exception
// in the callback cancels the run and is raised once the core has unwound.
struct PythonProgress {
  py::object callback;
  std::exception_ptr error;
  bool cancelled = false;  ///< the callback returned False (or raised)

  std::function<bool(const FlowProgress&)> hook() {
    if (callback.is_none()) return {};
    return [this](const FlowProgress& p) {
      py::gil_scoped_acquire gil;
      try {
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

// A keyword argument checked against the range of the filter parameter it stands for, the error
// in the caller's name ("max_steps must be >= 0", not the core's field names).
void checkArgument(app::FilterId filter, const char* parameter, const char* keyword, double value) {
  const app::FilterSpec spec = app::filterSpec(filter, {});
  const app::ParamSpec& p = *spec.param(parameter);
  if (value >= p.minValue && value <= p.maxValue) return;
  auto text = [](double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", x);
    return std::string(b);
  };
  const std::string range = p.maxValue < std::numeric_limits<double>::infinity()
                                ? "in " + text(p.minValue) + ".." + text(p.maxValue)
                                : ">= " + text(p.minValue);
  throw InvalidInputError(std::string(keyword) + " must be " + range + (p.rangeHint.empty() ? "" : " (" + p.rangeHint + ")") +
                          ", not " + text(value));
}

// ---- the functions --------------------------------------------------------------------------

py::tuple fairArrays(const py::object& V, const py::object& F, const py::object& selectedFaces,
                     const std::string& flow, const std::optional<std::string>& scheme, int subdivide,
                     long long maxSteps, double maxSeconds, double featureSize, std::optional<double> energyTol,
                     bool tangential, const std::string& boundary, bool remesh, bool flipEdges,
                     const py::object& progress) {
  using app::FilterId;
  checkArgument(FilterId::Fairing, "subdivisionLevels", "subdivide", subdivide);
  checkArgument(FilterId::Fairing, "maxSteps", "max_steps", double(maxSteps));
  checkArgument(FilterId::Fairing, "maxSeconds", "max_seconds", maxSeconds);
  if (energyTol) checkArgument(FilterId::Fairing, "energyTolerance", "energy_tol", *energyTol);
  // The MeshLab parameter is a length (its range has no upper end); here it is a fraction.
  if (!(featureSize >= 0 && featureSize <= 1))
    throw InvalidInputError("feature_size must be in 0..1 (a fraction of the bounding-box diagonal), not " +
                            std::to_string(featureSize));
  TriMesh mesh = toMesh(V, F);
  app::checkedTopology(mesh, /*rejectNonManifoldVertices=*/true, app::RepairHints::None);
  std::vector<std::uint8_t> selection = selectionFrom(selectedFaces, mesh.faceCount());
  FlowOptions opt;
  opt.flow = choice<FlowType>("flow", flow);
  if (scheme) opt.scheme = choice<Scheme>("scheme", *scheme);
  opt.subdivisionLevels = subdivide;
  opt.maxSteps = app::stepLimit(maxSteps);
  opt.maxSeconds = maxSeconds;
  opt.featureSize = featureSize * boundingBoxDiagonal(mesh.positions);
  if (energyTol) opt.energyTolerance = *energyTol;
  opt.tangentialDrift = tangential;
  opt.boundary = choice<BoundaryMode>("boundary", boundary);
  opt.remesh = remesh;
  opt.flipEdges = flipEdges;
  PythonProgress hook{progress, nullptr};
  opt.progress = hook.hook();
  const int inV = mesh.vertexCount(), inF = mesh.faceCount();
  app::FairingResult r = withoutGil(hook, [&] {
    return app::runFairing(std::move(mesh), std::move(selection), opt, /*outputCurvature=*/true);
  });
  return py::make_tuple(vertexArray(r.mesh), faceArray(r.mesh),
                        toPython(app::fairingReport(r.report, opt, inV, inF, &r)));
}

py::tuple fillArrays(const py::object& V, const py::object& F, int maxHoleEdges, bool closeRims, const std::string& flow,
                     const std::optional<std::string>& scheme, std::optional<long long> maxSteps, double maxSeconds,
                     const py::object& progress) {
  checkArgument(app::FilterId::FillHoles, "MaxHoleSize", "max_hole_edges", maxHoleEdges);
  if (maxSteps) checkArgument(app::FilterId::FillHoles, "maxSteps", "max_steps", double(*maxSteps));
  checkArgument(app::FilterId::FillHoles, "maxSeconds", "max_seconds", maxSeconds);
  TriMesh mesh = toMesh(V, F);
  app::checkFillInput(mesh, app::RepairHints::None);
  HoleFillOptions opt;
  opt.maxHoleEdges = maxHoleEdges;
  opt.closeRims = closeRims;
  opt.flow.flow = choice<FlowType>("flow", flow);
  if (scheme) opt.flow.scheme = choice<Scheme>("scheme", *scheme);
  if (maxSteps) opt.flow.maxSteps = app::stepLimit(*maxSteps);
  opt.flow.maxSeconds = maxSeconds;
  PythonProgress hook{progress, nullptr};
  opt.flow.progress = hook.hook();
  app::FillHolesResult r = withoutGil(hook, [&] { return app::runFillHoles(std::move(mesh), opt); });
  // fillHoles stops at the hole it was cancelled in: give back nothing rather than a part.
  if (hook.cancelled) throw Error("cancelled; nothing filled");
  py::array_t<bool> isNew(static_cast<py::ssize_t>(r.mesh.faceCount()));
  for (int f = 0; f < r.mesh.faceCount(); ++f) isNew.mutable_data()[f] = r.report.isNewFace(f);
  return py::make_tuple(vertexArray(r.mesh), faceArray(r.mesh), isNew, toPython(app::fillingReport(r, opt)));
}

py::dict curvatureArrays(const py::object& V, const py::object& F, const std::string& area, bool lambdaFix) {
  const TriMesh mesh = toMesh(V, F);
  app::checkedTopology(mesh, /*rejectNonManifoldVertices=*/false, app::RepairHints::None);
  CurvatureMeasureOptions opt;
  opt.area = choice<VertexArea>("area", area);
  opt.curvature.h2k = lambdaFix ? H2KTreatment::PaperLambda : H2KTreatment::Clamp;
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

py::tuple readFile(const py::object& pathLike) {
  const std::string path = pathOf(pathLike);
  const TriMesh mesh = io::readMesh(path).mesh;  // the CLI's reader: its checks, repairs and messages
  return py::make_tuple(vertexArray(mesh), faceArray(mesh));
}

void writeFile(const py::object& pathLike, const py::object& V, const py::object& F, bool ascii) {
  const std::string path = pathOf(pathLike);
  const TriMesh mesh = toMesh(V, F);
  io::writeMesh(path, mesh, {}, !ascii);  // by extension; atomic: a failed write leaves no half-written file
}

// ---- the MeshLab filters' parameters, for faces that build dialogs (the Blender add-on) ---------

// The Python keyword argument a filter parameter stands for; "" where the face decides (the
// selection, colouring, selecting new faces).
std::string keywordOf(const std::string& parameter) {
  static const std::map<std::string, std::string> keywords = {
      {"flow", "flow"},           {"scheme", "scheme"},         {"maxSteps", "max_steps"}, {"maxSeconds", "max_seconds"},
      {"subdivisionLevels", "subdivide"}, {"energyTolerance", "energy_tol"}, {"tangentialDrift", "tangential"},
      {"featureSize", "feature_size"},
      {"boundary", "boundary"},   {"MaxHoleSize", "max_hole_edges"}, {"CloseRims", "close_rims"}, {"lambdaFix", "lambda_fix"},
      {"area", "area"}};
  const auto it = keywords.find(parameter);
  return it == keywords.end() ? std::string() : it->second;
}

// The command-line words of a RichEnum's entries: the choices table whose labels they are.
template <class E>
bool wordsOf(const std::vector<std::string>& labels, std::vector<std::string>& words) {
  if (app::labels<E>() != labels) return false;
  for (const app::Choice<E>& c : app::choices<E>()) words.emplace_back(c.name);
  return true;
}
std::vector<std::string> enumWords(const std::vector<std::string>& labels) {
  std::vector<std::string> w;
  if (wordsOf<FlowType>(labels, w) || wordsOf<Scheme>(labels, w) || wordsOf<BoundaryMode>(labels, w) ||
      wordsOf<VertexArea>(labels, w) || wordsOf<H2KTreatment>(labels, w))
    return w;
  throw std::logic_error("no choices table for a RichEnum");  // a filter_spec.cpp change without one
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

py::dict filterSpecs() {
  static const std::map<app::FilterId, const char*> function = {
      {app::FilterId::Fairing, "fair"}, {app::FilterId::FillHoles, "fill_holes"}, {app::FilterId::Curvature, "curvature"}};
  py::dict all;
  // A diagonal of 1 makes a RichAbsPerc's default its fraction of the diagonal, which is what
  // Python takes (feature_size=0.03).
  app::MeshFacts unitDiagonal;
  unitDiagonal.diagonal = 1;
  for (const app::FilterSpec& f : app::allFilters(unitDiagonal)) {
    py::list params;
    for (const app::ParamSpec& p : f.params) {
      py::dict d;
      d["name"] = p.name;
      const std::string keyword = keywordOf(p.name);
      d["keyword"] = keyword.empty() ? py::object(py::none()) : py::object(py::str(keyword));
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
        case app::ParamType::Float:
          d["type"] = "float";
          d["default"] = typedDecimal(p.defaultValue);
          break;
        case app::ParamType::AbsPerc:  // a fraction of the bounding-box diagonal here
          d["type"] = "float";
          d["default"] = typedDecimal(p.defaultValue);
          d["description"] = p.tooltip + " A fraction of the bounding-box diagonal.";
          break;
        case app::ParamType::Enum: {
          d["type"] = "enum";
          const std::vector<std::string> words = enumWords(p.enumValues);
          d["choices"] = words;
          d["labels"] = p.enumValues;
          d["default"] = words.at(static_cast<std::size_t>(p.defaultValue));
          break;
        }
      }
      auto bound = [](double x) { return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none()); };
      if (p.type == app::ParamType::Int || p.type == app::ParamType::Float) {
        d["min"] = bound(p.minValue);
        d["max"] = bound(p.maxValue);
      }
      if (p.type == app::ParamType::AbsPerc) {
        d["min"] = 0.0;
        d["max"] = 1.0;
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

  const FlowOptions flowDefaults;
  const HoleFillOptions fillDefaults;
  m.def("fair", &fairArrays, py::arg("V"), py::arg("F"), py::arg("selected_faces") = py::none(), py::kw_only(),
        py::arg("flow") = app::nameOf(flowDefaults.flow), py::arg("scheme") = py::none(), py::arg("subdivide") = 0,
        py::arg("max_steps") = flowDefaults.maxSteps, py::arg("max_seconds") = 0.0, py::arg("feature_size") = 0.0,
        py::arg("energy_tol") = py::none(), py::arg("tangential") = true,
        py::arg("boundary") = app::nameOf(flowDefaults.boundary), py::arg("remesh") = flowDefaults.remesh,
        py::arg("flip_edges") = flowDefaults.flipEdges, py::arg("progress") = py::none(),
        (std::string("fair(V, F, selected_faces=None, *, flow='elastica', scheme=None, subdivide=0, max_steps=") +
         std::to_string(flowDefaults.maxSteps) +
         ", max_seconds=0, feature_size=0, energy_tol=None, tangential=True,\n     boundary='fixed',"
         " remesh=True, flip_edges=False, progress=None) -> (V_out, F_out, report)\n\n"
         "Fairs the mesh with a curvature flow, as `elastica fair`: flow 'elastica' (F = -Lap H - 2H(H^2-K)),\n"
         "'lmc' or 'bilaplacian'; scheme 'explicit', 'semi-implicit', 'vector' or 'auto' (None: the core's default, '" +
         app::nameOf(flowDefaults.scheme) +
         "');\n"
         "subdivide: coarse-to-fine 1-to-4 subdivisions (0..8); max_steps and max_seconds 0: no limit;\n"
         "feature_size: a fairing amount, a fraction of the bounding-box diagonal (bumps smaller than it are\n"
         "smoothed away, larger shapes kept; report['stop'] 'feature_size'), 0: fair until converged; energy_tol None: the\n"
         "default; boundary 'fixed' (boundary and next row clamped) or 'slide'. remesh (not explicit): the\n"
         "mesh-quality stages (pre-subdivision, isotropic remeshing of the moving region, edge flips, embedding\n"
         "guard), so F_out may differ from F; False keeps the connectivity (`--no-remesh`). flip_edges: flip\n"
         "non-Delaunay edges at every check (`--remesh`). selected_faces: face indices\n"
         "or a bool mask; only vertices whose faces are all selected move. progress(dict) -> bool is called at\n"
         "every check with level, step, energy, lambda, seconds; return False to cancel (raises elastica.Error).\n"
         "report: the dict `elastica fair --report` writes (without file names).")
            .c_str());
  m.def("fill_holes", &fillArrays, py::arg("V"), py::arg("F"), py::kw_only(),
        py::arg("max_hole_edges") = fillDefaults.maxHoleEdges, py::arg("close_rims") = fillDefaults.closeRims,
        py::arg("flow") = app::nameOf(fillDefaults.flow.flow),
        py::arg("scheme") = py::none(), py::arg("max_steps") = py::none(), py::arg("max_seconds") = 0.0,
        py::arg("progress") = py::none(),
        "fill_holes(V, F, *, max_hole_edges=500, close_rims=False, flow='elastica', scheme=None, max_steps=None,\n"
        "           max_seconds=0, progress=None) -> (V_out, F_out, new_faces, report)\n\n"
        "Fills every hole with at most max_hole_edges border edges, as `elastica fill`; an open surface's outer\n"
        "rim stays open unless close_rims (report['holes'][i]['rim'] tells which loops are rims). The input's vertices\n"
        "and faces come first, unchanged, and new_faces is True on the appended patch faces. scheme None: the\n"
        "fill's default (semi-implicit); max_steps None: the default budget. report: the dict\n"
        "`elastica fill --report` writes (without file names).");
  m.def("curvature", &curvatureArrays, py::arg("V"), py::arg("F"), py::kw_only(),
        py::arg("area") = app::nameOf(VertexArea::Mixed), py::arg("lambda_fix") = false,
        "curvature(V, F, *, area='mixed', lambda_fix=False) -> {'H': array, 'K': array, 'energy': float}\n\n"
        "Per-vertex mean curvature H (+1/r on a sphere with outward normals; H/lambda where the paper's lambda\n"
        "fix applies), angle-deficit Gaussian curvature K, and the total curvature energy E = sum (4H^2 - 2K) A,\n"
        "as `elastica curvature`. area: 'mixed' (Meyer et al.) or 'barycentric' (the paper's A/3).");
  m.def("read", &readFile, py::arg("path"),
        "read(path) -> (V, F)\n\nReads PLY, OFF, STL or OBJ with the `elastica` command's reader: polygons split,\n"
        "STL corners merged, degenerate and duplicate faces removed, bow-tie vertices split; a malformed file\n"
        "raises elastica.IoError naming what and where.");
  m.def("write", &writeFile, py::arg("path"), py::arg("V"), py::arg("F"), py::kw_only(), py::arg("ascii") = false,
        "write(path, V, F, *, ascii=False)\n\nWrites the format the extension names (.ply, .off, .obj, .stl; PLY and\n"
        "STL binary unless ascii) atomically: on failure the destination is left as it was; an unknown extension\n"
        "raises elastica.IoError.");
  m.def("filters", &filterSpecs,
        "filters() -> {'fair': spec, 'fill_holes': spec, 'curvature': spec}\n\n"
        "The MeshLab filters' parameters, for a face that builds a dialog (the Blender add-on): each spec has\n"
        "the filter's 'name' and 'info' (HTML) and 'parameters', a list of dicts with 'name' (the .mlx name),\n"
        "'keyword' (this module's keyword argument, or None where the caller decides: the selection, colouring,\n"
        "selecting new faces), 'type' ('bool', 'int', 'float', 'enum'), 'default', 'label', 'description', for\n"
        "numbers 'min' and 'max' (None: unbounded), for enums 'choices' (keyword values) and 'labels' (menu).\n"
        "Passing every keyword at its default runs what the MeshLab filter runs at its defaults.");
}
