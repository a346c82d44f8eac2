// A shaded 3-D picture of a periodic packing (PNG, gnuplot's pngcairo run by src/render/gnuplot.hpp):
// the particles of a 2 x 2 x 2 block of cells (each particle of the cell, its centre reduced
// into the cell, and its images shifted by the period vectors in {0, 1}^3), each drawn as the
// cube-sphere mesh of packing_mesh.hpp in the colour of its index in the cell, lit, depth
// sorted, with the edges of the first cell and of the block drawn as lines. Floating point: a
// picture of the certified configuration, not a part of its proof.
#pragma once
#include <string>

#include "superpack/arith/interval.hpp"
#include "superpack/problems/periodic/periodic_packing.hpp"

namespace superpack {

// Draws `packing` into the PNG `path`, titled with p, the particles per cell and the lower end
// of `phi` (rounded down); throws RenderError when gnuplot fails, leaving no file then.
// Call require_plottable(path) (plot.hpp) before the work that makes the packing.
void packing_png(const std::string& path, const PeriodicPacking& packing, const DInterval& phi);

}  // namespace superpack
