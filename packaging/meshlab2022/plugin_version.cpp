// SPDX-License-Identifier: GPL-3.0-or-later
// plugin_version: is PLUGIN built for the MeshLab of this libmeshlab-common? MeshLab 2022.02 and later
// load a plugin only if its baked version and precision match their own (PluginManager::checkPlugin).
//
//   plugin_version PLUGIN.so float|double
//
// Prints the plugin's baked MeshLab version and precision (MeshLabPlugin::getMLVersion(), compiled into
// the plugin from MESHLAB_VERSION and MESHLAB_SCALAR) and the host's version, read from the loaded
// libmeshlab-common where it exports one (meshlab::meshlabCompleteVersion(), 2025.07), else the
// version of the host's source tree this tool is built against (2022.02 exports none). Exit 0 only when
// the first 6 characters of both versions agree (checkPlugin's rule), the plugin's precision is the
// host build's (the argument: Debian's MeshLab is float) and the library's checkPlugin accepts the
// file; 1 otherwise, with the reason (also when the plugin does not load at all, as a plugin built
// for another MeshLab's ABI may not).
#include <common/globals.h>
#include <common/mlexception.h>
#include <common/plugins/interfaces/meshlab_plugin.h>
#include <common/plugins/plugin_manager.h>

#include <QCoreApplication>
#include <QFileInfo>
#include <QPluginLoader>

#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3 || (std::strcmp(argv[2], "float") != 0 && std::strcmp(argv[2], "double") != 0)) {
    std::fprintf(stderr, "usage: plugin_version PLUGIN.so float|double\n");
    return 2;
  }
  QCoreApplication app(argc, argv);
  const QString file = QFileInfo(QString::fromLocal8Bit(argv[1])).absoluteFilePath();
  const bool hostDouble = std::strcmp(argv[2], "double") == 0;
#ifdef ELASTICA_LIBRARY_VERSION
  const std::string host = meshlab::meshlabCompleteVersion();
#else
  const std::string host = meshlab::meshlabVersion();
#endif
  std::printf("host: MeshLab %s (libmeshlab-common), %s precision\n", host.c_str(), argv[2]);

  QPluginLoader loader(file);
  auto* plugin = dynamic_cast<MeshLabPlugin*>(loader.instance());
  if (plugin == nullptr) {
    std::printf("FAIL: %s is not a MeshLab plugin this MeshLab can load: %s\n", argv[1],
                qUtf8Printable(loader.errorString()));
    return 1;
  }
  const auto [version, isDouble] = plugin->getMLVersion();
  std::printf("plugin: built for MeshLab %s, %s precision\n", version.c_str(), isDouble ? "double" : "single");
  bool ok = true;
  if (version.substr(0, 6) != host.substr(0, 6)) {
    std::printf("FAIL: version %s is not the host's %s (first 6 characters)\n", version.c_str(), host.c_str());
    ok = false;
  }
  if (isDouble != hostDouble) {
    std::printf("FAIL: precision %s is not the host's %s\n", isDouble ? "double" : "float", argv[2]);
    ok = false;
  }
  try {
    PluginManager::checkPlugin(file);
    std::printf("checkPlugin: accepted\n");
  } catch (const MLException& e) {
    std::printf("checkPlugin: refused: %s\n", e.what());
    ok = false;
  }
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
