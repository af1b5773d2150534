// SPDX-License-Identifier: GPL-3.0-or-later
// The MeshLab plugin API the plugin is built for, chosen at configure time (CMake
// ELASTICA_MESHLAB_API, passed to the compiler and to moc as the macro of the same name):
//   2020  MeshLab 2020.09 (Debian 12): MeshFilterInterface in common/interfaces.h
//   2022  MeshLab 2022.02 (Debian 13): FilterPlugin in common/plugins/interfaces/filter_plugin.h
//   2025  MeshLab 2023.12 to 2025.07: the same FilterPlugin; RichAbsPerc became RichPercentage (its
//         .mlx type name stays "RichAbsPerc") and the parameters moved to common/parameters/
// The shared filter code (filter_common.h) sees the API only through this header; each API has
// its own thin plugin class (filter_elastica_2020.h, filter_elastica_2022.h, which 2025 shares).
#pragma once

#ifndef ELASTICA_MESHLAB_API
#error "ELASTICA_MESHLAB_API must be defined (2020, 2022 or 2025): set by meshlab_plugin/CMakeLists.txt"
#endif

#if ELASTICA_MESHLAB_API == 2025
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/interfaces/filter_plugin.h>
#elif ELASTICA_MESHLAB_API == 2022
#include <common/plugins/interfaces/filter_plugin.h>
#elif ELASTICA_MESHLAB_API == 2020
#include <common/interfaces.h>
#else
#error "ELASTICA_MESHLAB_API must be 2020, 2022 or 2025"
#endif

namespace elastica::meshlab {

#if ELASTICA_MESHLAB_API >= 2022
using FilterBase = FilterPlugin;  ///< the plugin interface (its FilterClass values are the same)
#else
using FilterBase = MeshFilterInterface;
#endif

/// A length shown with its percentage of the diagonal (read back with getAbsPerc in every API).
#if ELASTICA_MESHLAB_API >= 2025
using RichLength = RichPercentage;
#else
using RichLength = RichAbsPerc;
#endif

/// MeshLab's standard update after changing coordinates (bounding box, face and angle-weighted
/// vertex normals): renamed from UpdateBoxAndNormals to updateBoxAndNormals in 2021.
inline void updateBoxAndNormals(MeshModel& m) {
#if ELASTICA_MESHLAB_API >= 2022
  m.updateBoxAndNormals();
#else
  m.UpdateBoxAndNormals();
#endif
}

}  // namespace elastica::meshlab
