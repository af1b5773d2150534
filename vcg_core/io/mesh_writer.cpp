#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>
#include <elastica/io/mesh_writer.h>

#include <wrap/io_trimesh/export_ply.h>

#include <deque>
#include <string>

namespace elastica::io {

namespace vio = vcg::tri::io;
namespace {

// A float attribute of `m` (by name) to write as a PLY property of the same name. Not
// PlyInfo::AddPerElemFloatAttribute: it keeps pointers to the vectors of the first PlyInfo it
// ever sees in function-local statics (every later PlyInfo in the process writes into that dead
// object and saves none of its attributes) and strdup's names it never frees. `names` owns the
// property names (a deque: adding keeps the earlier ones in place) while `info` is in use.
void addFloatAttribute(vio::PlyInfo& info, std::deque<std::string>& names, bool face, const std::string& name) {
  names.push_back(name);
  (face ? info.FaceAttrNameVec : info.VertAttrNameVec).push_back(name);
  auto& descriptors = face ? info.FaceDescriptorVec : info.VertDescriptorVec;
  descriptors.push_back(vcg::ply::PropDescriptor());
  descriptors.back().elemname = face ? "face" : "vertex";
  descriptors.back().propname = names.back().c_str();
  descriptors.back().stotype1 = vcg::ply::T_FLOAT;
  descriptors.back().memtype1 = vcg::ply::T_FLOAT;
}

}  // namespace

void writePly(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt) {
  std::deque<std::string> names;
  vio::PlyInfo info;
  info.mask = vio::Mask::IOM_VERTCOORD | vio::Mask::IOM_FACEINDEX;
  if (opt.vertexQuality) info.mask |= vio::Mask::IOM_VERTQUALITY;
  if (opt.vertexColor) info.mask |= vio::Mask::IOM_VERTCOLOR;
  if (opt.vertexNormal) info.mask |= vio::Mask::IOM_VERTNORMAL;
  if (opt.faceFlags) info.mask |= vio::Mask::IOM_FACEFLAGS;
  for (const std::string& name : opt.faceFloatAttributes) addFloatAttribute(info, names, true, name);
  if (opt.curvature) {
    addFloatAttribute(info, names, false, "mean_curvature");
    addFloatAttribute(info, names, false, "gaussian_curvature");
  }
  writeAtomically(path, [&](const std::string& tmp) {
    const int err = vio::ExporterPLY<VcgMesh>::Save(m, tmp.c_str(), opt.binary, info);
    if (err != 0) throw IoError(path + ": writing failed (" + vio::ExporterPLY<VcgMesh>::ErrorMsg(err) + ")");
  });
}

}  // namespace elastica::io
