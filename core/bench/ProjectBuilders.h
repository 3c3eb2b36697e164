#pragma once
// Project files of the benchmark cases, built as JSON: the validation problems (cantilever, plate with a hole,
// Hertz's cylinder, Lamé's thick cylinder, a stretched patch) at any mesh size, and the solver settings of a mode.
#include <string>
#include <vector>

#include "base/Schema.h"

namespace rollsim::bench {

/// Solver labels of the suites: skyline, direct, mixed, feti-none, feti-lumped, feti-dirichlet.
bool is_iterative(const std::string& mode);
/// The `solver` object of a mode label at CG tolerance `tol` (ignored by direct modes), one thread. A label may
/// end in ":selective" (the Newton update policy), e.g. "mixed:selective".
json solver_json(const std::string& mode, double tol);

/// A 2D block body (Q4) of nx × ny elements over lx × ly from `origin`, material "m", `partition` for feti ("" none).
json block_body(const std::string& name, int nx, int ny, double lx, double ly, std::vector<double> origin,
                const std::string& partition);
/// The same in 3D (H8).
json block_body_3d(const std::string& name, std::vector<int> n, std::vector<double> size, const std::string& partition);
/// A project skeleton: dimension, one elastic material "m" (E, ν) and no bodies yet, no output files.
json project_skeleton(int dim, double e, double nu);

/// Timoshenko's end-loaded cantilever L = 8, D = 2 (plane strain, E 1000, ν 0.3) with `n` elements through the
/// depth (4n along), clamped at x = 0, a total tip force of −1 along y on x = 8; feti partition 4x2.
json cantilever_project(int n, const std::string& partition = "4x2");
/// Paper Example 3, the quarter plate with a hole (radius 1, quarter 4 × 4, uy 0.01 on top) with `n_around`
/// elements around the hole (0.75 n radially, the sample's grading spread); feti partition 2x2.
json plate_hole_project(int n_around);

/// Hertz's cylinder on a block (samples/cylinder-indent-2d.json) with mesh size h near the contact; the cylinder's
/// modulus `e_cylinder` (the block's is 1000), radius `radius` (a sector of arc length π/2 for R > 1: grazing
/// contact), lifted by `gap` above the block; the block in 2x2 subdomains for feti.
json hertz_project(double h, double e_cylinder = 1000, double radius = 1, double gap = 0);

/// Lamé's thick cylinder a = 1, b = 2, internal pressure 1 (quarter, plane strain, E 1000) with ν and the element
/// formulation ("full", "bbar"); 16 × 32 Q4 (`n_radial` × 2 n_radial); feti partition 2x2.
json thick_cylinder_project(double nu, const std::string& formulation, int n_radial);

/// A unit square of n × n Q4 stretched 1 % along x (ux = 0 on x = 0, uy = 0 on y = 0, ux = 0.01 on x = 1): the
/// patch test's constant stress σ_xx = E/(1 − ν²) · 0.01 in plane strain; feti partition 2x2.
json stretched_patch_project(int n, const std::string& formulation);

}  // namespace rollsim::bench
