#include "report/hole_report.h"

#include "pipeline/pipeline.h"
#include "report/hole_words.h"
#include "report/json_text.h"

#include <QString>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace curvature_inpaint {

std::string DescribeValidation(const ValidationRecord& v) {
  std::vector<std::string> candidates;
  for (const TriedFill& c : v.candidates) candidates.push_back(TriedFillName(c));
  const std::vector<double>& errors = v.errors;
  const int choice = v.chosen, fake_holes = v.fake_holes;
  if (candidates.empty()) return v.note.empty() ? "not validated" : v.note;
  std::ostringstream o;
  o << "on " << fake_holes << " fake hole" << (fake_holes == 1 ? "" : "s");
  if (v.mirror_fake_holes > 0) o << " (" << v.mirror_fake_holes << " at its mirror place)";
  o << ", RMS in % of the hole's radius:";
  for (size_t c = 0; c < candidates.size() && c < errors.size(); ++c)
    o << (c ? ", " : " ") << candidates[c] << " "
      << QString::number(100 * errors[c], 'f', 2).toStdString();
  if (choice >= 0 && size_t(choice) < candidates.size()) o << "; chose " << candidates[choice];
  if (v.not_clear >= 0 && size_t(v.not_clear) < candidates.size())
    o << " (" << candidates[size_t(v.not_clear)] << " did best, not clearly)";
  if (!v.note.empty()) o << " (" << v.note << ")";
  return o.str();
}

std::vector<std::string> DescribeVariations(const std::vector<HoleVariations>& holes) {
  std::vector<std::string> lines;
  for (size_t k = 0; k < holes.size(); ++k) {
    const HoleVariations& hv = holes[k];
    const std::string hole = "hole " + std::to_string(k + 1) + ": ";
    const HoleChoice& c = hv.choice;
    if (!c.validation.candidates.empty() || !c.validation.note.empty())
      lines.push_back(hole + "validation " + DescribeValidation(c.validation));
    if (hv.variations.empty()) {
      lines.push_back(hole + "no variations: " + c.problem);
      continue;
    }
    std::string line = hole + "variations";
    for (size_t j = 0; j < hv.variations.size(); ++j)
      line += (j ? ", " : " ") + std::to_string(j + 1) + " " + FillKindName(c.kinds[j]) +
              " (score " +
              QString::number(j < c.scores.size() ? c.scores[j] : 0, 'g', 4).toStdString() + ")";
    line += c.pick > 0 ? "; fill picks " + std::to_string(c.pick)
                       : std::string("; fill keeps the coarse fill");
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> DescribeHoleFill(const HoleFillResult& result) {
  std::vector<std::string> lines = DescribeCoarseFill(result.coarse);
  if (result.symmetry_detected)
    lines.push_back(
        DescribeSymmetry(result.symmetry, result.symmetry_best, result.symmetry_partial));
  char buf[512];
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleFillReport& r = result.holes[k];
    const HoleChoice& c = r.choice;
    if (!c.validation.candidates.empty() || !c.validation.note.empty())
      lines.push_back("validation " + std::to_string(k + 1) + ": " +
                      DescribeValidation(c.validation));
    if (!c.problem.empty()) {
      std::snprintf(buf, sizeof buf, "inpaint %zu: none: %s", k + 1, c.problem.c_str());
    } else {
      std::string scores;
      for (double s : c.scores) // "-": a variation listed, not made
        scores += (scores.empty() ? "" : " ") +
                  (std::isfinite(s) ? QString::number(s, 'g', 4).toStdString() : "-");
      const std::string kind =
          r.kind == FillKind::kContinuation ? "" : std::string(" ") + FillKindName(r.kind);
      std::snprintf(
          buf, sizeof buf,
          "inpaint %zu: %d edges, variation %d%s of %zu (scores %s), %d deformation steps, "
          "images %.0f ms, validation %.0f ms, inpaint %.0f ms, deform %.0f ms",
          k + 1, r.boundary_edges, c.pick, kind.c_str(), c.scores.size(), scores.c_str(),
          r.deformation.iterations, 1000 * r.seconds.images, 1000 * r.seconds.validation,
          1000 * r.seconds.inpaint, 1000 * r.seconds.deform);
    }
    lines.emplace_back(buf);
    if (!c.pick_note.empty() && c.problem.empty())
      lines.back() += ", " + c.pick_note + " (the automatic choice instead)";
    if (r.crease_flips > 0)
      lines.back() += ", " + std::to_string(r.crease_flips) + " fill edges flipped onto creases";
    if (c.priors.mirror_covered >= 0)
      lines.back() += ", mirror image on " +
                      std::to_string(std::lround(100 * c.priors.mirror_covered)) +
                      " % of the fill, its ring within " +
                      QString::number(100 * c.priors.mirror_ring_residual, 'f', 1).toStdString() +
                      " % of the hole's radius";
  }
  return lines;
}

std::vector<std::string> DescribeHolesInWords(const HoleFillResult& result) {
  std::vector<std::string> lines;
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleFillReport& r = result.holes[k];
    lines.push_back("hole " + std::to_string(k + 1) + " (" + std::to_string(r.boundary_edges) +
                    " edges): " + ChoiceInWords(r.choice));
  }
  return lines;
}

std::string HoleFillReportJson(const HoleFillResult& result, const HoleFillParams& params) {
  std::ostringstream o;
  o.precision(6);
  o << "{\n  \"backend\": " << JsonQuoted(BackendName(params.inpaint.backend))
    << ",\n  \"mode\": " << JsonQuoted(DeformationModeName(params.mode)) << ",\n";
  if (result.symmetry_detected) {
    auto planes = [&o](const std::vector<vcg_ext::SymmetryPlane>& list) {
      o << "[";
      for (size_t k = 0; k < list.size(); ++k) {
        const auto& p = list[k];
        o << (k ? ", " : "") << "{\"normal\": [" << JsonNumber{p.normal.x()} << ", "
          << JsonNumber{p.normal.y()} << ", " << JsonNumber{p.normal.z()}
          << "], \"offset\": " << JsonNumber{p.offset}
          << ", \"coverage\": " << JsonNumber{p.coverage}
          << ", \"residual\": " << JsonNumber{p.residual} << "}";
      }
      o << "]";
    };
    o << "  \"symmetry\": {\"seconds\": " << JsonNumber{result.symmetry_s} << ", \"planes\": ";
    planes(result.symmetry);
    o << ", \"partial_planes\": ";
    planes(result.symmetry_partial);
    o << ", \"best_coverage\": " << JsonNumber{result.symmetry_best.coverage} << "},\n";
  }
  o << "  \"holes\": [";
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleFillReport& r = result.holes[k];
    const HoleChoice& c = r.choice;
    const ValidationRecord& v = c.validation;
    o << (k ? ",\n" : "\n") << "    {\"hole\": " << k + 1
      << ", \"boundary_edges\": " << r.boundary_edges << ", \"new_vertices\": " << r.new_vertices
      << ", \"scores\": [";
    for (size_t j = 0; j < c.scores.size(); ++j) o << (j ? ", " : "") << JsonNumber{c.scores[j]};
    o << "], \"kinds\": [";
    for (size_t j = 0; j < c.kinds.size(); ++j)
      o << (j ? ", " : "") << JsonQuoted(FillKindName(c.kinds[j]));
    o << "]";
    if (!v.candidates.empty()) {
      o << ", \"validation\": {\"fake_holes\": " << v.fake_holes
        << ", \"at_mirror_place\": " << v.mirror_fake_holes
        << ", \"tie\": " << JsonNumber{params.validation.tie} << ", \"candidates\": [";
      for (size_t i = 0; i < v.candidates.size(); ++i)
        o << (i ? ", " : "") << "{\"name\": " << JsonQuoted(TriedFillName(v.candidates[i]))
          << ", \"error\": " << JsonNumber{v.errors[i]}
          << ", \"detail_ratio\": " << JsonNumber{v.detail[i]} << "}";
      o << "], \"per_fake_hole\": [";
      for (size_t f = 0; f < v.per_fake_hole.size(); ++f) {
        o << (f ? ", [" : "[");
        for (size_t i = 0; i < v.per_fake_hole[f].size(); ++i)
          o << (i ? ", " : "") << JsonNumber{v.per_fake_hole[f][i]};
        o << "]";
      }
      o << "], \"choice\": " << JsonQuoted(TriedFillName(v.Chosen()));
      if (v.not_clear >= 0)
        o << ", \"not_clearly_better\": "
          << JsonQuoted(TriedFillName(v.candidates[size_t(v.not_clear)]));
      if (!v.note.empty()) o << ", \"note\": " << JsonQuoted(v.note);
      o << "}";
    } else if (!v.note.empty()) {
      o << ", \"validation\": {\"note\": " << JsonQuoted(v.note) << "}";
    }
    o << ", \"pick\": " << c.pick;
    if (r.kind != FillKind::kCoarse) o << ", \"kind\": " << JsonQuoted(FillKindName(r.kind));
    o << ", \"crease_flips\": " << r.crease_flips;
    o << ", \"iterations\": " << r.deformation.iterations
      << ", \"backoffs\": " << r.deformation.backoffs
      << ", \"max_move\": " << JsonNumber{r.deformation.max_move}
      << ", \"seconds\": {\"coarse\": " << JsonNumber{r.seconds.coarse}
      << ", \"images\": " << JsonNumber{r.seconds.images}
      << ", \"validation\": " << JsonNumber{r.seconds.validation}
      << ", \"inpaint\": " << JsonNumber{r.seconds.inpaint}
      << ", \"deform\": " << JsonNumber{r.seconds.deform} << "}";
    if (params.measure_detail)
      o << ", \"curvature_spread\": {\"truth\": " << JsonNumber{r.truth_spread.truth}
        << ", \"truth_image\": " << JsonNumber{r.truth_spread.image}
        << ", \"target\": " << JsonNumber{r.target_spread}
        << ", \"result\": " << JsonNumber{r.result_spread} << "}";
    if (c.priors.mirror_covered >= 0)
      o << ", \"mirror_image\": {\"covered\": " << JsonNumber{c.priors.mirror_covered}
        << ", \"ring_residual\": " << JsonNumber{c.priors.mirror_ring_residual} << "}";
    if (!c.priors.no_symmetry.empty())
      o << ", \"no_symmetry\": " << JsonQuoted(c.priors.no_symmetry);
    if (!c.priors.no_creases.empty()) o << ", \"no_creases\": " << JsonQuoted(c.priors.no_creases);
    if (!c.problem.empty()) o << ", \"problem\": " << JsonQuoted(c.problem);
    o << "}";
  }
  o << "\n  ]\n}\n";
  return o.str();
}

} // namespace curvature_inpaint
