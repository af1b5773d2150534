// SPDX-License-Identifier: GPL-3.0-or-later
// amount_operators IN OUT EDGES cotangent|graph: the fairing amount's filter with the operators
// named, at EDGES mean edge lengths (of the faces, as the report counts them), for
// bench/amount_operators_sweep.py (docs/options.md, "The default amount"). No halving: the core's
// fair() as asked. Binary PLY.
#include <elastica/app/fairing_amount.h>
#include <elastica/fairing.h>
#include <elastica/flow.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "guarded_main.h"

using namespace elastica;

namespace {

int fairWithOperators(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: amount_operators IN OUT EDGES cotangent|graph\n");
    return 2;
  }
  TriMesh m = io::readMesh(argv[1]).mesh;
  FlowOptions opt;
  opt.featureSize = std::atof(argv[3]) * app::meanFaceEdge(m, nullptr);
  opt.amountOperators = std::strcmp(argv[4], "graph") == 0 ? AmountOperators::Graph : AmountOperators::Cotangent;
  const FlowReport r = fair(m, opt);
  io::writePly(argv[2], m, {}, true);
  std::printf("{\"energy_before\": %.9g, \"energy_after\": %.9g}\n", r.energyInitial, r.energyFinal);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return bench::guardedMain("amount_operators", fairWithOperators, argc, argv); }
