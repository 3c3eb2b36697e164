// Structured Q4 annulus / annular sector generator and the ring layout shared with the cylinder generator.
#include "mesh/Annulus.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rollsim {

namespace detail {

namespace {
constexpr double kFullTurnTolerance = 1e-9;  // degrees

void require(bool ok, const char* spec, const char* message) {
  if (!ok) throw std::invalid_argument(std::string(spec) + "." + message);
}
}  // namespace

RingLayout::RingLayout(double theta0_deg, double theta1_deg, int n)
    : theta0(theta0_deg),
      span(theta1_deg - theta0_deg),
      n_around(n),
      closed(std::abs(theta1_deg - theta0_deg - 360.0) <= kFullTurnTolerance) {}

std::array<double, 2> RingLayout::direction(int i) const {
  const double deg = i == n_around && closed ? theta0 : theta0 + span * i / n_around;
  const double quarter = deg / 90.0;
  if (quarter == std::floor(quarter) && std::abs(quarter) < 1e9) {
    static const double c[4] = {1.0, 0.0, -1.0, 0.0}, s[4] = {0.0, 1.0, 0.0, -1.0};
    const int k = ((static_cast<int>(quarter) % 4) + 4) % 4;
    return {c[k], s[k]};
  }
  const double rad = deg * std::numbers::pi / 180.0;
  return {std::cos(rad), std::sin(rad)};
}

int RingLayout::rank(int i, int n) const {
  if (!closed) return i;
  return 2 * i < n ? 2 * i : 2 * (n - i) - 1;
}

int RingLayout::position(int r, int n) const {
  if (!closed) return r;
  return r % 2 == 0 ? r / 2 : n - (r + 1) / 2;
}

void validate_ring(const char* spec, double inner_radius, double outer_radius, int n_radial, int n_around,
                   double theta0, double theta1) {
  require(std::isfinite(inner_radius) && inner_radius > 0.0, spec, "inner_radius must be positive");
  require(std::isfinite(outer_radius) && outer_radius > inner_radius, spec,
          "outer_radius must be larger than inner_radius");
  require(n_radial >= 1, spec, "n_radial must be at least 1");
  require(n_around >= 1, spec, "n_around must be at least 1");
  require(std::isfinite(theta0), spec, "theta0 must be finite");
  require(std::isfinite(theta1) && theta1 > theta0, spec, "theta1 must be larger than theta0");
  require(theta1 - theta0 <= 360.0 + kFullTurnTolerance, spec, "theta1 - theta0 must not exceed 360 degrees");
  require((theta1 - theta0) / n_around < 180.0, spec,
          "n_around is too small: each element must span less than 180 degrees");
}

}  // namespace detail

namespace {
void validate(const AnnulusSpec& s) {
  if (!std::isfinite(s.cx) || !std::isfinite(s.cy)) throw std::invalid_argument("AnnulusSpec.cx/cy must be finite");
  detail::validate_ring("AnnulusSpec", s.inner_radius, s.outer_radius, s.n_radial, s.n_around, s.theta0, s.theta1);
}

// Node / element numbering of the (around i, radial j) grid: the direction with fewer nodes varies fastest.
struct Numbering {
  const detail::RingLayout& ring;
  int n_radial;
  bool radial_fast;
  int node(int i, int j) const {
    const int na = ring.positions(), r = ring.rank(i % na, na);
    return radial_fast ? j + r * (n_radial + 1) : r + j * na;
  }
  // (i, j) of element e
  std::array<int, 2> element(int e) const {
    const int n = ring.n_around;
    if (radial_fast) return {ring.position(e / n_radial, n), e % n_radial};
    return {ring.position(e % n, n), e / n};
  }
};

void add_nodes(Mesh& m, const AnnulusSpec& s, const detail::RingLayout& ring, const Numbering& num) {
  m.nodes.resize(static_cast<size_t>(ring.positions()) * (s.n_radial + 1));
  for (int i = 0; i < ring.positions(); ++i) {
    const auto d = ring.direction(i);
    for (int j = 0; j <= s.n_radial; ++j) {
      const double t = static_cast<double>(j) / s.n_radial;
      const double r = (1.0 - t) * s.inner_radius + t * s.outer_radius;
      m.nodes[num.node(i, j)] = {s.cx + r * d[0], s.cy + r * d[1], 0.0};
    }
  }
}

void add_elements(Mesh& m, const AnnulusSpec& s, const detail::RingLayout& ring, const Numbering& num) {
  auto& all = m.element_sets["all"];
  for (int e = 0; e < s.n_around * s.n_radial; ++e) {
    const auto [i, j] = num.element(e);
    // radial edge first, then along the ring: counter-clockwise
    for (int v : {num.node(i, j), num.node(i, j + 1), num.node(i + 1, j + 1), num.node(i + 1, j)})
      m.connectivity.push_back(v);
    if (j == 0) m.surfaces["inner"].push_back({e, 3});
    if (j == s.n_radial - 1) m.surfaces["outer"].push_back({e, 1});
    if (!ring.closed && i == 0) m.surfaces["start"].push_back({e, 0});
    if (!ring.closed && i == s.n_around - 1) m.surfaces["end"].push_back({e, 2});
    all.push_back(e);
  }
}
}  // namespace

Mesh make_annulus(const AnnulusSpec& s) {
  validate(s);
  const detail::RingLayout ring(s.theta0, s.theta1, s.n_around);
  const Numbering num{ring, s.n_radial, s.n_radial + 1 <= ring.positions()};
  Mesh m;
  m.dim = 2;
  m.type = ElementType::Quad4;
  add_nodes(m, s, ring, num);
  add_elements(m, s, ring, num);
  add_derived_node_sets(m);
  return m;
}

}  // namespace rollsim
