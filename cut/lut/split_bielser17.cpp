#include "cut/lut/split_bielser17.h"

namespace mtcut::cut {

SplitRecipe generate_bielser17_split(const TetConfig& config) {
  TraceOptions options;
  options.split_face_nodes = true;
  const CutTrace tr = trace_cut(config, options);
  SplitRecipe recipe;
  recipe.kind = config.cut_case();
  recipe.centre_of = tr.surface;
  // The centre is split when nothing joins the two sides inside the tet: no
  // uncut crossing (an unsplit vertex on the plane only ends the cut).
  bool split_centre = true;
  for (const SectionPoint& p : tr.section) split_centre &= p.active || p.is_vertex;
  for (const TraceTriangle& t : tr.triangles) {
    const LabelSide side = split_centre ? t.side : LabelSide::kNone;
    recipe.tets.push_back({make_label(LabelKind::kCentre, 0, side), t.v[0], t.v[1], t.v[2]});
  }
  return recipe;
}

}  // namespace mtcut::cut
