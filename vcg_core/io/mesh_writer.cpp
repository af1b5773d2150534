#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>
#include <elastica/io/mesh_writer.h>

#include <wrap/io_trimesh/export_ply.h>

namespace elastica::io {

void writePly(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt) {
  namespace vio = vcg::tri::io;
  vio::PlyInfo info;
  info.mask = vio::Mask::IOM_VERTCOORD | vio::Mask::IOM_FACEINDEX;
  if (opt.vertexQuality) info.mask |= vio::Mask::IOM_VERTQUALITY;
  if (opt.vertexColor) info.mask |= vio::Mask::IOM_VERTCOLOR;
  if (opt.vertexNormal) info.mask |= vio::Mask::IOM_VERTNORMAL;
  if (opt.faceFlags) info.mask |= vio::Mask::IOM_FACEFLAGS;
  for (const std::string& name : opt.faceFloatAttributes) info.AddPerFaceFloatAttribute(name.c_str());
  if (opt.curvature) {
    info.AddPerVertexFloatAttribute("mean_curvature");
    info.AddPerVertexFloatAttribute("gaussian_curvature");
  }
  writeAtomically(path, [&](const std::string& tmp) {
    const int err = vio::ExporterPLY<VcgMesh>::Save(m, tmp.c_str(), opt.binary, info);
    if (err != 0) throw IoError(path + ": writing failed (" + vio::ExporterPLY<VcgMesh>::ErrorMsg(err) + ")");
  });
}

}  // namespace elastica::io
