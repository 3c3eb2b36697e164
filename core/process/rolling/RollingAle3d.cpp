#include "process/rolling/RollingAle3d.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "analysis/AnalysisError.h"

namespace rollsim {

namespace {
/// The bilinear map of a quad's four corners projected on the x-y plane: (s, t) in [−1, 1]² holding (x, y), or false.
bool inside_xy(const std::array<std::array<double, 3>, 4>& q, double x, double y, double& s, double& t) {
  constexpr int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  s = t = 0;
  for (int it = 0; it < 20; ++it) {
    Eigen::Vector2d r(-x, -y);
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
    for (int a = 0; a < 4; ++a) {
      const double N = 0.25 * (1 + sx[a] * s) * (1 + sy[a] * t);
      const double ds = 0.25 * sx[a] * (1 + sy[a] * t), dt = 0.25 * sy[a] * (1 + sx[a] * s);
      r += N * Eigen::Vector2d(q[a][0], q[a][1]);
      J.col(0) += ds * Eigen::Vector2d(q[a][0], q[a][1]);
      J.col(1) += dt * Eigen::Vector2d(q[a][0], q[a][1]);
    }
    if (std::abs(J.determinant()) < 1e-14) return false;
    const Eigen::Vector2d d = J.inverse() * r;
    s -= d[0], t -= d[1];
    if (d.norm() < 1e-12) break;
  }
  return std::abs(s) <= 1 + 1e-9 && std::abs(t) <= 1 + 1e-9;
}
}  // namespace

RollingAle3d::RollingAle3d(const RollingPass& pass, const Model& model)
    : slab_(pass.slab), roll_(pass.roll), surface_(pass, model) {
  const Mesh& slab = model.bodies[static_cast<size_t>(slab_)].mesh;
  // a column: the nodes of one (x, y), by height; a line: the nodes of one (y, level), by x
  std::map<std::pair<double, double>, std::vector<int>> columns;
  for (int n = 0; n < slab.num_nodes(); ++n) {
    const auto& X = slab.nodes[static_cast<size_t>(n)];
    columns[{X[0], X[1]}].push_back(n);
  }
  std::map<std::pair<double, size_t>, std::vector<int>> lines;
  size_t levels = 0;
  for (auto& [xy, nodes] : columns) {
    std::sort(nodes.begin(), nodes.end(), [&](int a, int b) { return slab.nodes[a][2] < slab.nodes[b][2]; });
    levels = std::max(levels, nodes.size());
    for (size_t k = 0; k < nodes.size(); ++k) lines[{xy.second, k}].push_back(nodes[k]);
    x_.push_back(xy.first);  // the map's keys are sorted by x: equal ones run together
  }
  x_.erase(std::unique(x_.begin(), x_.end()), x_.end());
  for (auto& [key, nodes] : lines) {
    std::sort(nodes.begin(), nodes.end(), [&](int a, int b) { return slab.nodes[a][0] < slab.nodes[b][0]; });
    if (nodes.size() != x_.size()) throw std::logic_error("ALE rolling: the slab's window is not a structured block");
    lines_.push_back(nodes);
    top_.push_back(key.second + 1 == levels);
    entry_of_.push_back(slab.nodes[static_cast<size_t>(nodes.front())]);
  }
  entry_ = slab.node_sets.at("xmin");
  const Mesh& roll = model.bodies[static_cast<size_t>(roll_)].mesh;
  for (const Facet& f : roll.surfaces.at("outer")) {
    const std::vector<int> local = facet_local_nodes(roll.type, f.local);
    std::array<int, 4> q{};
    for (int a = 0; a < 4; ++a) q[static_cast<size_t>(a)] = roll.element(f.element)[local[static_cast<size_t>(a)]];
    roll_facets_.push_back(q);
  }
}

namespace {
/// Where a material line (its nodes `line` at `slab`, by x) crosses the plane x = X, X in its segment `seg` (or
/// beyond the line's ends, held there): across the width (y) the cubic through the segment's nodes and their
/// neighbours where the line has them, held within the segment's ends' values; in height (z), and at the line's
/// ends, the segment's chord. A chord across the width smeared the free side's bulge along the line at every step (a
/// numerical diffusion over a spacing): the 16 × 8 × 4 window's mean spread still grew at 150 mm, with the cubic it
/// levels off. In height the window's top has kinks (flat, the arc, flat), where a cubic overshoots: the 24 × 12 × 8
/// window, which rolls 20 mm with chords, diverged within its first millimetre.
std::array<double, 3> crossing(const MeshMotion::Positions& slab, const std::vector<int>& line, size_t seg, double X) {
  const auto& a = slab[static_cast<size_t>(line[seg])];
  const auto& b = slab[static_cast<size_t>(line[seg + 1])];
  const double t = std::clamp((X - a[0]) / (b[0] - a[0]), 0.0, 1.0);  // held beyond the line's ends
  std::array<double, 3> p{X, a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
  if (seg < 1 || seg + 2 >= line.size() || X < a[0] || X > b[0]) return p;
  const std::array<const std::array<double, 3>*, 4> q = {&slab[static_cast<size_t>(line[seg - 1])], &a, &b,
                                                         &slab[static_cast<size_t>(line[seg + 2])]};
  double y = 0;
  for (size_t k = 0; k < 4; ++k) {
    double L = 1;  // Lagrange's basis on the four nodes' x
    for (size_t m = 0; m < 4; ++m)
      if (m != k) L *= (X - (*q[m])[0]) / ((*q[k])[0] - (*q[m])[0]);
    y += L * (*q[k])[1];
  }
  p[1] = std::clamp(y, std::min(a[1], b[1]), std::max(a[1], b[1]));  // no overshoot past the segment's ends
  return p;
}
}  // namespace

double RollingAle3d::roll_under(double x, double y, const Positions& roll) const {
  double under = std::numeric_limits<double>::infinity();
  for (const auto& f : roll_facets_) {
    std::array<std::array<double, 3>, 4> q;
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (size_t a = 0; a < 4; ++a) {
      q[a] = roll[static_cast<size_t>(f[a])];
      lo_x = std::min(lo_x, q[a][0]), hi_x = std::max(hi_x, q[a][0]);
      lo_y = std::min(lo_y, q[a][1]), hi_y = std::max(hi_y, q[a][1]);
    }
    double s, t;
    if (x < lo_x || x > hi_x || y < lo_y || y > hi_y || !surface_.lower(q[0]) || !inside_xy(q, x, y, s, t)) continue;
    constexpr int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    double z = 0, r = 0;
    for (size_t a = 0; a < 4; ++a) {
      const double N = 0.25 * (1 + sx[a] * s) * (1 + sy[a] * t);
      z += N * q[a][2], r += N * surface_.radius(q[a]);
    }
    under = std::min(under, surface_.round ? surface_.lower_side(x, r) : z);
  }
  return under;
}

MeshMotion::Positions RollingAle3d::placed(const std::vector<Positions>& current,
                                           const std::vector<char>& touching) const {
  const Positions& slab = current[static_cast<size_t>(slab_)];
  const Positions& roll = current[static_cast<size_t>(roll_)];
  Positions out = slab;
  for (size_t l = 0; l < lines_.size(); ++l) {
    const std::vector<int>& line = lines_[l];
    for (size_t i = 1; i < line.size(); ++i)
      if (!(slab[static_cast<size_t>(line[i])][0] > slab[static_cast<size_t>(line[i - 1])][0]))
        throw AnalysisError("the slab's lines of nodes along x have folded over themselves: they cannot be followed");
    size_t seg = 0;
    for (size_t i = 0; i < line.size(); ++i) {
      const double X = x_[i];
      while (seg + 2 < line.size() && slab[static_cast<size_t>(line[seg + 1])][0] < X) ++seg;
      // the entry plane, where the material has flowed in: its virgin section (held to the line's first moved node,
      // the entry face kept whatever the step's bulge ahead of the arc gave it, and the window's width grew)
      std::array<double, 3> p = crossing(slab, line, seg, X);
      if (i == 0 && slab[static_cast<size_t>(line[0])][0] > X) p = entry_of_[l];
      if (top_[l]) {
        const double under = roll_under(X, p[1], roll);
        if (std::isfinite(under) && (touching[static_cast<size_t>(line[i])] || p[2] > under)) p[2] = under;
      }
      if (!(p[2] >= 0)) {
        char text[160];
        std::snprintf(text, sizeof text, "the slab has no thickness left at x = %.4g mm", X);
        throw AnalysisError(text);
      }
      out[static_cast<size_t>(line[i])] = p;
    }
  }
  return out;
}

bool RollingAle3d::inflow(const std::array<double, 3>& p, const Positions& current) const {
  double best = std::numeric_limits<double>::infinity(), x = 0;  // the entry face's node nearest across the section
  for (int n : entry_) {
    const auto& c = current[static_cast<size_t>(n)];
    const double d = std::hypot(c[1] - p[1], c[2] - p[2]);
    if (d < best) best = d, x = c[0];
  }
  return p[0] < x;
}

std::string RollingAle3d::describe() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "the slab's mesh held from x = %.4g to %.4g mm (%zu planes, %zu lines along x), its material flowing "
                "through",
                x_.front(), x_.back(), x_.size(), lines_.size());
  return text;
}

}  // namespace rollsim
