#include "cut/lut/piece_filler.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using Tet4 = std::array<Label, 4>;
using Tri = std::array<Label, 3>;

// The same oriented triangle starts at its smallest label.
Tri canonical(Tri t) {
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

Tri reversed(const Tri& t) { return canonical({t[0], t[2], t[1]}); }

std::array<Tri, 4> outward_faces(const Tet4& t) {
  std::array<Tri, 4> out;
  for (int f = 0; f < 4; ++f) {
    const auto& lf = engine::kTetFaces[f];
    out[f] = canonical({t[lf[0]], t[lf[1]], t[lf[2]]});
  }
  return out;
}

double volume(const LabelPositions& p, const Tet4& t) {
  return volume6(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) / 6.0;
}

// A canonical oriented triangle packed in one word.
std::uint32_t pack(const Tri& t) { return t[0] | static_cast<std::uint32_t>(t[1]) << 8 | static_cast<std::uint32_t>(t[2]) << 16; }

class Filler {
 public:
  Filler(const std::vector<Tri>& boundary, const std::vector<LabelPositions>& realisations)
      : realisations_(realisations) {
    std::vector<Label> points;
    for (const Tri& t : boundary) {
      add(pack(canonical(t)), +1);
      points.insert(points.end(), t.begin(), t.end());
      const auto& p = realisations.front();
      target_ += p[t[0]].dot(p[t[1]].cross(p[t[2]])) / 6.0;
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    const std::size_t n = points.size();
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        for (std::size_t c = b + 1; c < n; ++c)
          for (std::size_t d = c + 1; d < n; ++d) {
            Tet4 t = {points[a], points[b], points[c], points[d]};
            if (volume(realisations.front(), t) < 0) std::swap(t[2], t[3]);
            const bool positive = std::all_of(realisations.begin(), realisations.end(), [&](const LabelPositions& p) {
              const double scale = volume6(p[0], p[make_label(LabelKind::kVertex, 1)],
                                                         p[make_label(LabelKind::kVertex, 2)],
                                                         p[make_label(LabelKind::kVertex, 3)]);
              return volume(p, t) > 1e-14 * std::abs(scale);
            });
            if (!positive) continue;
            Candidate cand{t, {}, {}, volume(realisations.front(), t)};
            const auto faces = outward_faces(t);
            for (int f = 0; f < 4; ++f) {
              cand.faces[f] = pack(faces[f]);
              cand.reversed[f] = pack(reversed(faces[f]));
              by_face_[cand.faces[f]].push_back(candidates_.size());
            }
            candidates_.push_back(cand);
          }
  }

  std::optional<std::vector<Tet4>> run(int max_tets, long budget) {
    budget_ = budget;
    for (int limit = 1; limit <= max_tets && budget_ > 0; ++limit) {
      chosen_.clear();
      if (search(limit, 0.0)) return chosen_;
    }
    return std::nullopt;
  }

 private:
  struct Candidate {
    Tet4 tet;
    std::array<std::uint32_t, 4> faces;     // outward, canonical, packed
    std::array<std::uint32_t, 4> reversed;  // the same, inward
    double volume;
  };

  int count(std::uint32_t f) const {
    for (const auto& [g, n] : front_)
      if (g == f) return n;
    return 0;
  }
  void add(std::uint32_t f, int delta) {
    for (std::size_t i = 0; i < front_.size(); ++i)
      if (front_[i].first == f) {
        if ((front_[i].second += delta) == 0) {
          front_[i] = front_.back();
          front_.pop_back();
        }
        return;
      }
    front_.push_back({f, delta});
  }

  bool search(int limit, double filled) {
    if (--budget_ < 0) return false;
    if (front_.empty()) return std::abs(filled - target_) <= 1e-9 * std::abs(target_);
    if (static_cast<int>(chosen_.size()) >= limit || filled > target_ * (1 + 1e-9)) return false;
    // The most constrained face of the front first.
    const std::vector<std::size_t>* options = nullptr;
    for (const auto& [f, n] : front_) {
      const auto it = by_face_.find(f);
      if (it == by_face_.end()) return false;  // nothing can close this face
      if (!options || it->second.size() < options->size()) options = &it->second;
    }
    for (std::size_t index : *options) {
      const Candidate& cand = candidates_[index];
      // A face on the front is closed, any other opens inward; opening a
      // face that is already open would use it twice the same way.
      bool clash = false;
      for (int f = 0; f < 4; ++f)
        if (!count(cand.faces[f]) && count(cand.reversed[f])) clash = true;
      if (clash) continue;
      std::array<std::pair<std::uint32_t, int>, 4> undo;
      for (int f = 0; f < 4; ++f) {
        if (count(cand.faces[f])) {
          undo[f] = {cand.faces[f], +1};
          add(cand.faces[f], -1);
        } else {
          undo[f] = {cand.reversed[f], -1};
          add(cand.reversed[f], +1);
        }
      }
      chosen_.push_back(cand.tet);
      if (search(limit, filled + cand.volume)) return true;
      chosen_.pop_back();
      for (const auto& [f, delta] : undo) add(f, delta);
    }
    return false;
  }

  const std::vector<LabelPositions>& realisations_;
  std::vector<std::pair<std::uint32_t, int>> front_;  // triangles bounding what is left, outward from it
  std::vector<Candidate> candidates_;
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> by_face_;  // outward face -> candidates
  std::vector<Tet4> chosen_;
  double target_ = 0;
  long budget_ = 0;
};

}  // namespace

std::optional<std::vector<Tet4>> fill_piece(const std::vector<Tri>& boundary,
                                            const std::vector<LabelPositions>& realisations, int max_tets,
                                            long budget) {
  if (boundary.empty() || realisations.empty()) return std::nullopt;
  return Filler(boundary, realisations).run(max_tets, budget);
}

}  // namespace mtcut::cut
