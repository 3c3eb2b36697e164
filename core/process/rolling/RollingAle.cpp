#include "process/rolling/RollingAle.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "analysis/AnalysisError.h"

namespace rollsim {

namespace {
/// y of the polyline `points` (sorted by x) at x, held constant beyond its ends.
double along(const std::vector<std::array<double, 2>>& points, double x) {
  if (x <= points.front()[0]) return points.front()[1];
  if (x >= points.back()[0]) return points.back()[1];
  const auto hi = std::lower_bound(points.begin(), points.end(), x,
                                   [](const std::array<double, 2>& p, double v) { return p[0] < v; });
  const auto lo = hi - 1;
  const double t = ((*hi)[0] - (*lo)[0]) > 0 ? (x - (*lo)[0]) / ((*hi)[0] - (*lo)[0]) : 0.0;
  return (*lo)[1] + t * ((*hi)[1] - (*lo)[1]);
}
}  // namespace

RollingAle::RollingAle(const RollingPass& pass, const Model& model)
    : slab_(pass.slab), roll_(pass.roll), surface_(pass, model) {
  const Mesh& slab = model.bodies[static_cast<size_t>(slab_)].mesh;
  if (slab.dim != 2) throw std::logic_error("ALE rolling: plane strain only");
  std::map<double, std::vector<int>> by_x;
  for (int n = 0; n < slab.num_nodes(); ++n) by_x[slab.nodes[static_cast<size_t>(n)][0]].push_back(n);
  for (auto& [x, nodes] : by_x) {
    Column c;
    c.x = x;
    std::sort(nodes.begin(), nodes.end(), [&](int a, int b) { return slab.nodes[a][1] < slab.nodes[b][1]; });
    c.nodes = nodes;
    const double top = slab.nodes[static_cast<size_t>(nodes.back())][1];
    for (int n : nodes) c.share.push_back(slab.nodes[static_cast<size_t>(n)][1] / top);
    columns_.push_back(std::move(c));
  }
  entry_ = columns_.front().nodes;
  entry_height_ = slab.nodes[static_cast<size_t>(entry_.back())][1];
  const Mesh& roll = model.bodies[static_cast<size_t>(roll_)].mesh;
  for (const Facet& f : roll.surfaces.at("outer")) {
    const std::vector<int> local = facet_local_nodes(roll.type, f.local);
    roll_edges_.push_back({roll.element(f.element)[local[0]], roll.element(f.element)[local[1]]});
  }
}

double RollingAle::top_at(double x, const Top& top, const Positions& roll) const {
  double under = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : roll_edges_) {  // the roll's lower side: the lowest of its edges that span x
    const double x0 = roll[a][0], x1 = roll[b][0];
    if (x < std::min(x0, x1) || x > std::max(x0, x1) || x0 == x1 || !surface_.lower(roll[a])) continue;
    const double t = (x - x0) / (x1 - x0);
    under = std::min(under, surface_.round ? surface_.lower_side(
                                                 x, surface_.radius(roll[a]) * (1 - t) + surface_.radius(roll[b]) * t)
                                           : roll[a][1] + (roll[b][1] - roll[a][1]) * t);
  }
  const std::array<double, 2>&p = top.before_last_free, &q = top.last_free;
  if (x < top.arc_from && x > q[0] && q[0] > p[0])  // entering: the free top's line until it meets the roll
    return std::min(under, q[1] + (x - q[0]) * (q[1] - p[1]) / (q[0] - p[0]));
  if (x >= top.arc_from && x <= top.arc_to && std::isfinite(under)) return under;
  return std::min(along(top.surface, x), under);
}

MeshMotion::Positions RollingAle::placed(const std::vector<Positions>& current,
                                         const std::vector<char>& touching) const {
  const Positions& slab = current[static_cast<size_t>(slab_)];
  const Positions& roll = current[static_cast<size_t>(roll_)];
  Top top;  // the slab's top after the step, by x
  for (const Column& c : columns_) {
    const std::array<double, 3>& p = slab[static_cast<size_t>(c.nodes.back())];
    top.surface.push_back({p[0], p[1]});
    if (touching[static_cast<size_t>(c.nodes.back())]) {
      top.arc_from = std::min(top.arc_from, p[0]);
      top.arc_to = std::max(top.arc_to, p[0]);
    } else if (std::isinf(top.arc_to)) {
      top.before_last_free = top.last_free;
      top.last_free = {p[0], p[1]};
    }
  }
  if (!std::is_sorted(top.surface.begin(), top.surface.end()))
    throw AnalysisError("the slab's top surface has folded over itself: it cannot be followed");
  Positions out = slab;
  for (const Column& c : columns_) {
    // the entry column, where material has flowed in: its virgin height (RollingAle3d: the entry face kept each
    // step's rise ahead of the arc)
    const bool inflowed = &c == &columns_.front() && slab[static_cast<size_t>(c.nodes.back())][0] > c.x;
    const double height = inflowed ? entry_height_ : top_at(c.x, top, roll);
    if (!(height > 0)) {
      char text[160];
      std::snprintf(text, sizeof text, "the slab has no thickness left at x = %.4g mm", c.x);
      throw AnalysisError(text);
    }
    for (size_t j = 0; j < c.nodes.size(); ++j) out[static_cast<size_t>(c.nodes[j])] = {c.x, c.share[j] * height, 0.0};
  }
  return out;
}

bool RollingAle::inflow(const std::array<double, 3>& p, const Positions& current) const {
  std::vector<std::array<double, 2>> face;  // the entry face after the step: x by height
  for (int n : entry_) face.push_back({current[static_cast<size_t>(n)][1], current[static_cast<size_t>(n)][0]});
  return p[0] < along(face, p[1]);
}

std::string RollingAle::describe() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "the slab's mesh held from x = %.4g to %.4g mm (%zu columns), its material flowing through",
                columns_.front().x, columns_.back().x, columns_.size());
  return text;
}

}  // namespace rollsim
