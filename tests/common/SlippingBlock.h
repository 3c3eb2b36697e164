#pragma once
// A block on a base under Coulomb friction (μ 0.3), every point of the block's bottom active and slipping for good
// (its switches used up), each with its own normal force, both bodies moved at random over the step so that each point
// slips its own way: what the friction law's and its stiffness's tests update.
#include <random>

#include "contact/ContactConstraints.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace testing_support {

/// A 1 × 1 (× 1) block on a 2 × 2 (× 0.5) base, its bottom nodes inside the base's facets (weights away from 0, 1).
inline rollsim::Model block_on_base(int dim) {
  using json = nlohmann::json;
  const bool three = dim == 3;
  const json base =
      three ? json{{"type", "block"}, {"nx", 4},   {"ny", 4},   {"nz", 1},
                   {"lx", 2.0},       {"ly", 2.0}, {"lz", 0.5}, {"origin", {0.0, 0.0, -0.5}}}
            : json{{"type", "block"}, {"nx", 4}, {"ny", 1}, {"lx", 2.0}, {"ly", 0.5}, {"origin", {0.0, -0.5}}};
  const json block =
      three ? json{{"type", "block"}, {"nx", 2},   {"ny", 2},   {"nz", 1},
                   {"lx", 1.0},       {"ly", 1.0}, {"lz", 0.5}, {"origin", {0.45, 0.55, 0.0}}}
            : json{{"type", "block"}, {"nx", 2}, {"ny", 1}, {"lx", 1.0}, {"ly", 0.5}, {"origin", {0.45, 0.0}}};
  const std::string top = three ? "zmax" : "ymax", bottom = three ? "zmin" : "ymin";
  const json j = {
      {"name", "block-on-base"},
      {"dimension", dim},
      {"materials", {{{"name", "m"}, {"E", 1000.0}, {"nu", 0.3}}}},
      {"bodies",
       {{{"name", "base"}, {"material", "m"}, {"mesh", base}},
        {{"name", "block"}, {"material", "m"}, {"mesh", block}}}},
      {"contacts",
       {{{"name", "c"},
         {"type", "coulomb"},
         {"friction", 0.3},
         {"slave_body", "block"},
         {"slave_surface", bottom},
         {"master_body", "base"},
         {"master_surface", top},
         {"search_distance", 0.1}}}},
      {"boundary_conditions", {{{"type", "displacement"}, {"body", "base"}, {"set", bottom}, {"ux", 0.0}}}}};
  return rollsim::build_model(rollsim::parse_project(j.dump(), "test.json"));
}

/// Every point active and slipping (for good: switches used up), its normal row's multiplier −(1 + 0.1 r).
struct Slipping {
  rollsim::Model model;
  std::vector<rollsim::PairState> pairs;
  std::vector<rollsim::ConstraintRow> rows;
  Eigen::VectorXd lambda;
  std::vector<Eigen::VectorXd> start, u;  // the step's start (at rest) and the iterate, moved at random
};

inline Slipping slipping(int dim) {
  Slipping s{block_on_base(dim), {}, {}, {}, {}, {}};
  s.pairs = rollsim::search_contacts(s.model);
  rollsim::PairState& p = s.pairs.at(0);
  for (size_t j = 0; j < p.points.size(); ++j) p.active[j] = 1, p.slip[j] = 1, p.switches[j] = 2;
  s.rows = rollsim::contact_rows(s.model, s.pairs);
  s.lambda.resize(static_cast<Eigen::Index>(s.rows.size()));
  for (Eigen::Index r = 0; r < s.lambda.size(); ++r) s.lambda[r] = -1.0 - 0.1 * static_cast<double>(r);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> d(-0.01, 0.01);
  for (const rollsim::Body& b : s.model.bodies) {
    s.start.push_back(Eigen::VectorXd::Zero(b.mesh.num_nodes() * dim));
    s.u.emplace_back(b.mesh.num_nodes() * dim);
    for (Eigen::Index i = 0; i < s.u.back().size(); ++i) s.u.back()[i] = d(gen);
  }
  return s;
}

}  // namespace testing_support
