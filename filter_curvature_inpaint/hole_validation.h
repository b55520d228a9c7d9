// Fake-hole validation: a hole's candidate fills (the coarse fill, the embedded inpainter at
// each detail amplitude, the priors the hole has) each fill fake holes of its size cut into
// known surface near it, are scored against the surface cut out, and the one that validated
// best is the hole's choice (fake_holes.h cuts them).
#pragma once

#include "curvature_images.h"
#include "hole_fill.h"
#include "symmetry_prior.h"

#include <vcg_ext/coarse_fill.h>
#include <vcg_ext/hole_segmentation.h>

#include <string>

namespace curvature_inpaint {

/// What the validation reads of the mesh being filled (never written while holes run).
struct ValidationContext {
  const CMeshO* mesh = nullptr;
  const vcg_ext::CoarseFillResult* coarse = nullptr; ///< the holes' coarse fills (always given)
  const vcg_ext::VertexFaces* vf = nullptr;          ///< null where no hole is validated
  const SymmetryPrior* symmetry = nullptr;           ///< null where the prior is off
  int threads = 1; ///< for one hole's fake holes: what the holes in parallel leave over
};

/// Fake-hole validation of hole `hi` (embedded backend): every candidate (the coarse fill, the
/// embedded inpainter at each detail amplitude, the exemplar if asked for, with `continued` the
/// tri-Laplacian fill, with `symmetric` the mirror image's curvature and surface, with a
/// `crease_kind` the crease fill: each prior only where the hole itself has it) fills fake holes
/// of its size near it and is scored against the surface that was cut out; `hv` gets the
/// candidates, their errors and the choice (-1 when there was no room for fake holes: the variation
/// score then chooses alone). `ctx.vf` must be given.
void ValidateHole(const HoleImage& hi, const HoleFillParams& params, const InpaintParams& inpaint,
                  const ValidationContext& ctx, bool continued, bool symmetric,
                  const std::string& crease_kind, HoleVariations& hv);

} // namespace curvature_inpaint
