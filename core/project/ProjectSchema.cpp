// Declaration of every project field: name, type, range, default, unit, documentation.
#include "project/ProjectSchema.h"

#include "analysis/IncrementOptions.h"
#include "analysis/NewtonOptions.h"
#include "base/SchemaFields.h"
#include "io/OutputFields.h"
#include "material/FlowStress.h"
#include "material/ThermalTableSchema.h"
#include "process/ProcessRegistry.h"
#include "project/HeatProject.h"
#include "project/RunProject.h"
#include "solve/SolverStrategy.h"
#include "solve/UpdatePolicy.h"

namespace rollsim {

namespace {

using namespace schema;

/// A block's geometric grading along `axis` (a bias toward either face).
Field block_grading(const std::string& axis) {
  Field f = def(num(axis + "_grading", "-",
                    "size ratio of each element along " + axis + " to its neighbour on the +" + axis +
                        " side (1: uniform; > 1: elements shrink geometrically toward " + axis + " max, < 1: toward " +
                        axis + " min)" + (axis == "z" ? "; 3D only" : "")),
                1.0);
  f.min = 0.5;
  f.max = 2.0;
  if (axis == "z") f.default_value = nullptr;  // 3D only: a 2D model that gives it is told so
  return f;
}

const ObjectSchema kBlock{
    "block mesh",
    "Structured rectangle (Q4) or box (H8) of nx × ny (× nz) elements.",
    {req(count("nx", "elements along x", 1e5)), req(count("ny", "elements along y", 1e5)),
     count("nz", "elements along z (3D only, required there)", 1e5), req(positive("lx", "length", "extent along x")),
     req(positive("ly", "length", "extent along y")),
     positive("lz", "length", "extent along z (3D only, required there)"),
     vec("origin", "length", "corner with the smallest coordinates (default: the origin)"), block_grading("x"),
     block_grading("y"), block_grading("z")},
    "",
    {}};

Field grading() {
  Field f =
      def(num("grading", "-", "radial size ratio of each element to its neighbour nearer the hole (1: uniform)"), 1.0);
  f.min = 1.0;
  f.max = 2.0;
  return f;
}

const ObjectSchema kPlate{
    "plate_with_hole mesh",
    "Quarter of a rectangular plate with a central circular hole (2D); symmetry lines x = 0 and y = 0.",
    {req(positive("width", "length", "half-width W of the plate (x extent)")),
     req(positive("height", "length", "half-height H of the plate (y extent)")),
     req(positive("radius", "length", "hole radius a")),
     req(count("n_around", "elements around the quarter hole (even)", 1e5)),
     req(count("n_radial", "elements from the hole to the outer edges", 1e5)), grading()},
    "",
    {}};

Field angle(std::string name, double d, std::string doc) {
  Field f = def(num(std::move(name), "degree", std::move(doc)), d);
  f.min = -360;
  f.max = 360;
  return f;
}

const ObjectSchema kAnnulus{
    "annulus mesh",
    "Disk / annulus (2D roll), optionally a sector.",
    {req(vec("center", "length", "centre of the disk", 2)), req(positive("inner_radius", "length", "hub radius")),
     req(positive("outer_radius", "length", "outer radius")), req(count("n_radial", "elements across the ring", 1e5)),
     req(count("n_around", "elements around the span", 1e5)),
     angle("start_angle", 0.0, "start of the angular span, from +x towards +y"),
     angle("end_angle", 360.0, "end of the angular span (360 after 0: a closed ring)")},
    "",
    {}};

const ObjectSchema kRadiusPoint{
    "profile point",
    "The outer radius's change at one position along the axis; linear between points, constant beyond the first "
    "and the last.",
    {req(num("y", "length", "position along the axis")),
     req(num("radius_change", "length", "change of the outer radius there (negative: smaller)"))},
    "",
    {}};

const ObjectSchema kCylinder{
    "cylinder mesh",
    "Hollow cylinder with its axis along y (3D roll), optionally a sector.",
    {req(vec("center", "length", "axis position in the x-z plane [x, z]", 2)),
     def(num("y0", "length", "axial start"), 0.0), req(positive("length", "length", "axial length")),
     req(positive("inner_radius", "length", "hub radius")), req(positive("outer_radius", "length", "outer radius")),
     req(count("n_radial", "elements across the ring", 1e5)), req(count("n_around", "elements around the span", 1e5)),
     req(count("n_axial", "elements along the axis", 1e5)),
     angle("start_angle", 0.0, "start of the angular span in the x-z plane, from +x towards +z"),
     angle("end_angle", 360.0, "end of the angular span"),
     objects("outer_profile", kRadiusPoint,
             "a crowned, tapered or grooved barrel: the outer radius along y is outer_radius plus the profile's "
             "change, by ascending y, sampled at the axial nodes (give n_axial so that nodes fall on its corners); "
             "empty: a straight barrel")},
    "",
    {}};

const ObjectSchema kRoundBar{
    "round_bar mesh",
    "Solid round bar with its axis along z (3D): the quarter x ≥ 0, y ≥ 0 of its section (symmetry planes x = 0 and "
    "y = 0) meshed as an o-grid — a square core and a ring around it — swept from z = 0 to z = length. z = 0 is "
    "where the neck is (the mid-length symmetry plane of a whole bar: model half the bar, one eighth of it in all); "
    "the radius may grow linearly from neck_ratio × radius there to the full radius at taper_length, the geometric "
    "imperfection of Simo's necking benchmark. Lengths in the project's unit (the samples use mm).",
    {req(positive("radius", "length", "full radius R of the bar")),
     req(positive("length", "length", "axial extent (half the bar when z = 0 is its mid-length symmetry plane)")),
     req(count("n_core", "elements along each edge of the square core; the quarter circumference has 2 × n_core", 1e4)),
     req(count("n_ring", "elements across the ring, from the core to the round surface", 1e4)),
     req(count("n_axial", "elements along z", 1e5)),
     def(bounded(num("core_fraction", "-", "half-side of the square core over the radius"), 0.2, 0.7), 0.5),
     [] {
       Field f = def(num("neck_ratio", "-",
                         "radius at z = 0 over the full radius: the necking imperfection (0.982 in Simo's benchmark; "
                         "1: a straight bar)"),
                     1.0);
       f.min = 0.5;
       f.max = 1.0;
       return f;
     }(),
     positive("taper_length", "length",
              "axial extent over which the radius grows linearly from neck_ratio × radius to the full radius, at most "
              "length (default: the whole length)"),
     def(bounded(num("axial_grading", "-",
                     "size ratio of each element along z to its neighbour nearer z = 0 (1: uniform; > 1: finer at the "
                     "neck)"),
                 0.5, 2.0),
         1.0)},
    "",
    {}};

const ObjectSchema kDisk{
    "disk mesh",
    "Solid disk (2D, in the x-y plane) or solid cylinder with its axis along y (3D: the section in the x-z plane, as "
    "`cylinder`), meshed as an o-grid — in each quarter a square core and a ring around it, so no element degenerates "
    "at the centre — over whole quarters: the whole disk, a half or a quarter (its straight edges `start` and `end` "
    "then symmetry lines). A solid roll, a die, the cylinder of a Hertz or NAFEMS contact benchmark. Surfaces "
    "`outer`, `start` and `end` (a span short of 360°), in 3D `ymin` and `ymax`; node set `center` (the centre, in "
    "3D the axis).",
    {req(vec("center", "length", "centre: [x, y] in 2D, the axis position [x, z] in 3D", 2)),
     req(positive("radius", "length", "radius")),
     req(count("n_core",
               "elements along each edge of a quarter's square core; a quarter of the circumference has 2 × "
               "n_core",
               1e4)),
     req(count("n_ring", "elements across the ring, from the core to the round surface", 1e4)),
     def(bounded(num("core_fraction", "-", "half-side of a quarter's square core over the radius"), 0.2, 0.7), 0.5),
     angle("start_angle", 0.0, "start of the span, a multiple of 90: from +x towards +y (3D: towards +z)"),
     angle("end_angle", 360.0, "end of the span, a multiple of 90 (360 after 0: the whole disk)"),
     num("y0", "length", "3D: axial start (default 0)"),
     positive("length", "length", "3D: axial length (required there)"),
     count("n_axial", "3D: elements along the axis (required there)", 1e5)},
    "",
    {}};

const ObjectSchema kImport{
    "imported mesh",
    "A mesh read from a file, the reader chosen by its extension: .inp, a CalculiX / Abaqus input deck (*NODE, "
    "*ELEMENT, *NSET, *ELSET, *SURFACE with TYPE=ELEMENT, *INCLUDE; other keywords are not read). Linear "
    "quadrilaterals (CPE4, CPS4, CAX4 and their R/H/I variants; z = 0) in 2D, hexahedra (C3D8 and variants) in 3D; "
    "triangles, tetrahedra, wedges and quadratic elements are refused. The deck's node sets and element-face surfaces "
    "become the body's sets, named in lower case (CalculiX upper-cases names); each surface is also a node set, and "
    "`all` holds every node. .msh, a Gmsh mesh (version 4 or 2, ASCII or binary), read by Gmsh's own library "
    "(libgmsh, loaded on first use): linear quadrangles in 2D, hexahedra in 3D (recombined, first order); its physical "
    "groups are the sets — of the model's dimension an element set, of one less a surface (its lines or quadrangles "
    "matched to the elements' faces), every group a node set; an unnamed group is `physical_<tag>`. The element "
    "formulation, material and kinematics are the body's, never the file's.",
    {req(str("file", "the mesh file; a relative path is relative to the project file's folder")),
     str("element_set",
         "the file's element set (.msh: physical group) holding this body's elements (default: every element), "
         "e.g. E_SLAB of a deck written by `rollsim export-ccx`")},
    "",
    {}};

const ObjectSchema kMesh{"mesh",
                         "Mesh generator of a body, selected by `type`.",
                         {},
                         "type",
                         {{"block", &kBlock},
                          {"plate_with_hole", &kPlate},
                          {"annulus", &kAnnulus},
                          {"cylinder", &kCylinder},
                          {"round_bar", &kRoundBar},
                          {"disk", &kDisk},
                          {"import", &kImport}}};

Field tolerance() {
  Field f = num("tolerance", "length", "distance tolerance of `box` (default: 1e-6 of the body size)");
  f.min = 0.0;
  return f;
}

const ObjectSchema kNodeSet{
    "node set",
    "A named node set defined geometrically: the node nearest to a point, or all nodes inside a box.",
    {req(str("name", "set name, unique within the body")), vec("nearest", "length", "point: the nearest node"),
     vec("box_min", "length", "lower corner of a box"), vec("box_max", "length", "upper corner of a box"), tolerance()},
    "",
    {}};

const ObjectSchema kBody{
    "body",
    "A deformable body: mesh, material, element formulation, extra node sets.",
    {req(str("name", "body name, unique")), req(str("material", "name of an entry of `materials`")),
     choice("formulation", {"full", "bbar"}, "full",
            "full: 2×2(×2) Gauss integration; bbar: selective B-bar (F-bar with finite kinematics), for "
            "near-incompressibility and plastic flow"),
     choice("kinematics", {"small", "finite"}, "small",
            "small strain, or finite strain (large displacements and rotations; logarithmic strains, the Newton "
            "analysis)"),
     [] {
       Field f;
       f.name = "mesh";
       f.kind = Kind::Object;
       f.object = &kMesh;
       f.required = true;
       f.doc = "mesh generator";
       return f;
     }(),
     objects("node_sets", kNodeSet, "extra named node sets"),
     str("partition",
         "subdomains for the `feti` solver: \"AxB\" / \"AxBxC\" slices along x, y (, z) by element centroid, or "
         "\"metis:N\" (METIS k-way on the element dual graph); --partition overrides"),
     vec("partition_map", "-",
         "explicit element → subdomain map (integers from 0, one per element, e.g. painted in the window); excludes "
         "`partition`",
         -1)},
    "",
    {}};

Field poisson() {
  Field f = req(num("nu", "-", "Poisson's ratio"));
  f.min = -1.0;
  f.max = 0.5;
  f.min_exclusive = f.max_exclusive = true;
  return f;
}

const ObjectSchema kMaterial{
    "material",
    "Isotropic material: linear elastic, or elastoplastic (J2, isotropic hardening) when it has a yield stress: "
    "σ_y(α) = yield_stress + hardening_modulus·α + (saturation_stress − yield_stress)(1 − "
    "exp(−saturation_exponent·α)), "
    "α the equivalent plastic strain; or when it has a flow_stress law of strain, strain rate and temperature (hot "
    "forming). A plastic body is solved by the Newton analysis.",
    {req(str("name", "material name, unique")),
     [] {
       Field f = choice("model", {"linear_elastic", "j2_plasticity"}, "",
                        "constitutive model (default: j2_plasticity when yield_stress is given, else linear_elastic)");
       f.default_value = json();
       return f;
     }(),
     req(positive("E", "stress", "Young's modulus")), poisson(),
     positive("yield_stress", "stress", "initial yield stress σ_0 (J2 plasticity)"),
     def(non_negative("hardening_modulus", "stress", "linear isotropic hardening modulus H"), 0.0),
     positive("saturation_stress", "stress", "saturation stress σ_∞ ≥ σ_0 of the exponential hardening term"),
     def(non_negative("saturation_exponent", "-", "exponent δ of the saturation term"), 0.0),
     [] {
       Field f = object("flow_stress", flow_stress_schema(),
                        "a flow stress law σ_f(α, α̇, T) instead of yield_stress and its hardening (J2 plasticity)");
       f.default_value = json();
       return f;
     }(),
     def(bounded(num("temperature", "°C",
                     "the initial temperature of the bodies made of it, uniform (what a flow_stress law is taken at; "
                     "plastic work raises it where heat_capacity is given)"),
                 -273.15, 5000),
         20.0),
     positive("heat_capacity", "stress/K",
              "volumetric heat capacity ρc (MPa/K = J/(cm³·K) with mm and MPa; hot steel about 4.9): with it, plastic "
              "work heats each point, ΔT = β ∫ τ_y dα / ρc — adiabatically, or conducted away with a conductivity — "
              "and a flow_stress law softens with it. With a thermal_table.heat_capacity instead, conduction takes "
              "ρc(T) from the table and the table's value at `temperature` is this constant: the factor of plastic "
              "work's adiabatic rise within a mechanical step, which the heat step turns back into the same energy "
              "β ∫ τ_y dα"),
     def(bounded(num("taylor_quinney", "-", "β: the share of plastic work turned into heat (with heat_capacity)"), 0,
                 1),
         0.9),
     positive("conductivity", "W/(m·K)",
              "thermal conductivity k (= N/(s·K) with mm, N and s; steel about 30 hot, 45 cold): with "
              "heat_capacity, the bodies made of it conduct heat (the `heat` section; analysis.duration needed). "
              "With a thermal_table.conductivity instead, k(T) from the table"),
     [] {
       Field f = object("thermal_table", thermal_table_schema(),
                        "conductivity and heat capacity against temperature, for heat conduction (a material that "
                        "conducts): each property the table gives replaces its constant");
       f.default_value = json();
       return f;
     }()},
    "",
    {}};

Field where(std::string what) { return req(str("set", "name of a " + what + " of the body")); }

const ObjectSchema kDisp{
    "displacement condition",
    "Prescribed displacement per component on a node set (unset: free).",
    {req(str("body", "body name")), where("node set"), num("ux", "length", "prescribed x displacement"),
     num("uy", "length", "prescribed y displacement"), num("uz", "length", "prescribed z displacement (3D)")},
    "",
    {}};
const ObjectSchema kSym{"symmetry condition",
                        "Symmetry plane: zero normal displacement on a node set.",
                        {req(str("body", "body name")), where("node set"),
                         [] {
                           Field f = choice("normal", {"x", "y", "z"}, "", "normal of the symmetry plane");
                           f.default_value = nullptr;
                           f.required = true;
                           return f;
                         }()},
                        "",
                        {}};
const ObjectSchema kRotation{
    "rotation condition",
    "Prescribed rigid rotation of a node set about an axis, applied in increments (at load factor λ the angle is "
    "λ · angle, exact at any angle): u = (R − I)(X − center) + (ux, uy, uz). Every component of the set's nodes is "
    "prescribed. Drives a roll by its hub.",
    {req(str("body", "body name")), where("node set"), req(vec("center", "length", "a point of the axis")),
     vec("axis", "-", "direction of the axis (3D, required; 2D: the z axis, not given)", 3),
     req(num("angle", "degree", "rotation angle at the end of the analysis, right-hand rule about the axis")),
     num("ux", "length", "x translation added to the rotation"), num("uy", "length", "y translation"),
     num("uz", "length", "z translation (3D)")},
    "",
    {}};
const ObjectSchema kForce{"force condition",
                          "Force applied at every node of a set (per node, not shared).",
                          {req(str("body", "body name")), where("node set"), num("fx", "force", "x component"),
                           num("fy", "force", "y component"), num("fz", "force", "z component (3D)")},
                          "",
                          {}};
const ObjectSchema kPressure{
    "pressure condition",
    "Uniform pressure on a surface, positive into the body (negative: tension). 2D: force per unit length and "
    "unit thickness.",
    {req(str("body", "body name")), req(str("surface", "name of a surface of the body")),
     req(num("value", "stress", "pressure")),
     def(boolean("follower",
                 "true: the pressure follows the surface as it deforms — normal to the deformed surface, per unit "
                 "of its current area (a gas or a liquid's pressure); its load stiffness enters the Newton "
                 "tangent symmetrized, as the solvers factor a symmetric matrix (quadratic convergence where the "
                 "load is conservative, e.g. a closed or held surface). Needs the body's finite kinematics. false: "
                 "a dead load on the undeformed surface"),
         false)},
    "",
    {}};

const ObjectSchema kTraction{
    "traction condition",
    "Uniform traction on a surface: a force per unit area in any direction (shear and normal), on the undeformed "
    "surface — a dead load, which neither turns nor grows as the surface moves. 2D: force per unit length and unit "
    "thickness. Unset components: 0.",
    {req(str("body", "body name")), req(str("surface", "name of a surface of the body")),
     num("tx", "stress", "x component"), num("ty", "stress", "y component"), num("tz", "stress", "z component (3D)")},
    "",
    {}};
const ObjectSchema kBodyForce{
    "body force condition",
    "Uniform body force on every element of a body: force per unit undeformed volume (weight: density × g, e.g. "
    "7.85e-9 t/mm³ × 9810 mm/s² = 7.7e-5 N/mm³ for steel in mm, N). 2D: per unit thickness. Unset components: 0.",
    {req(str("body", "body name")), num("bx", "force/volume", "x component"), num("by", "force/volume", "y component"),
     num("bz", "force/volume", "z component (3D)")},
    "",
    {}};

const ObjectSchema kBC{"boundary condition",
                       "Boundary condition or load, selected by `type`.",
                       {},
                       "type",
                       {{"displacement", &kDisp},
                        {"symmetry", &kSym},
                        {"rotation", &kRotation},
                        {"force", &kForce},
                        {"pressure", &kPressure},
                        {"traction", &kTraction},
                        {"body_force", &kBodyForce}}};

const ObjectSchema kSurfaceTurn{
    "turning master surface",
    "The master surface's material turns about an axis while its mesh stays in place: a roll's surface moving under "
    "a mesh that does not turn (an Eulerian roll — its elastic field is steady in space, so a linear elastic roll "
    "with small kinematics is assembled and factored once). A sticking point moves with the turning material and a "
    "slipping one slips against it. Large sliding only; not with a conductance (the master's heat would stay where "
    "its mesh is).",
    {req(vec("center", "length", "a point of the axis")),
     vec("axis", "-", "direction of the axis (3D, required; 2D: the z axis, not given)", 3),
     req(num("angle", "degree", "the turn at the end of the analysis, right-hand rule about the axis"))},
    "",
    {}};
const ObjectSchema kContact{
    "contact pair",
    "Contact between two bodies through Lagrange multipliers on the slave surface's nodes (node-to-segment in 2D, "
    "node-to-face in 3D; meshes need not match). Small sliding: master facets and normals are found once, in the "
    "undeformed configuration; large sliding (Newton analysis): searched again in the current configuration at "
    "every iteration, so a slave node travels along the master surface. A body held only by contact (no displacement "
    "condition) is a floating body: "
    "`direct` and `mixed` solve it, `skyline` refuses it.",
    {req(str("name", "pair name, unique (the key of results.contact in summary.json)")),
     choice("type", {"tied", "frictionless", "sticking", "coulomb"}, "tied",
            "tied: bilateral, every component held (glue); frictionless: normal only, unilateral, with an active "
            "set; sticking: unilateral, and a point in contact keeps its place on the master (no slip: the paper's "
            "infinite friction); coulomb: unilateral, sticks while the tangential force is below μ times the normal "
            "force and slips with μ times it (Newton analysis)"),
     non_negative("friction", "-", "Coulomb's friction coefficient μ (coulomb pairs only, required there)"),
     non_negative("shear_limit", "stress",
                  "sticking and coulomb pairs: the friction stress never exceeds this (a point slips once its "
                  "tangential force passes shear_limit × its tributary length or area; Tresca's cap, e.g. the shear "
                  "yield stress σ_0/√3 of a hot slab; 0 or absent: no cap)"),
     bounded(positive("slip_tolerance", "-",
                      "coulomb pairs and sticking pairs with a shear_limit (default 0.005): the elastic slip δ of a "
                      "slipping point as a fraction of its facet size (√ of its tributary area in 3D, its tributary "
                      "length in 2D; Abaqus's default). Its friction force points along its trial force δ d₀ − v_t "
                      "(d₀ its direction where the step began, v_t its slip over the step): Coulomb's −v_t/|v_t| once "
                      "it has slipped far against δ; a point whose trial force falls inside the cone sticks. Smaller "
                      "is nearer Coulomb's law; larger holds a point that slips next to nothing to its direction "
                      "(docs/BENCHMARKS-ROLLING.md: the 3D pass's force within 0.1 % between 0.005 and 5e-5)"),
             0, 0.1),
     req(str("slave_body", "body carrying the multipliers")), req(str("slave_surface", "surface of the slave body")),
     req(str("master_body", "the other body")), req(str("master_surface", "surface of the master body")),
     choice("sliding", {"small", "large", "large_every_iteration"}, "small",
            "unilateral pairs: small sliding (the projection of the undeformed configuration), or large (Newton "
            "analysis) — searched again where each step begins, its Newton iterations keeping that projection "
            "(quadratic convergence), and again wherever the step converged while the projections moved by more "
            "than 1e-8 of the search distance; or at every Newton iteration, the rows' change with the displacement "
            "then linearised (analysis.contact_tangent: the contact's geometric stiffness). Where little "
            "slides, small sliding converges fastest (docs/BENCHMARKS-NONLINEAR.md). "
            "The linear analysis always slides small"),
     positive("search_distance", "length",
              "slave nodes farther from the master surface are ignored (default: 1e-6 of the model size for tied, "
              "5 % of the model size for frictionless)"),
     non_negative("conductance", "kW/(m²·K)",
                  "heat transfer across the pair where it touches, h_c (T_master − T_slave) per unit area (= "
                  "N/(mm·s·K) with mm, N and s; roll and hot slab 10–50): both bodies must conduct (the `heat` "
                  "section)"),
     [] {
       Field f = object("master_turns", kSurfaceTurn, "the master surface's material turns under a mesh that stays");
       f.default_value = json();
       return f;
     }(),
     def(bounded(num("friction_heat_to_slave", "-",
                     "the share of the friction work (friction force × slip) that heats the slave body; the rest "
                     "heats the master"),
                 0, 1),
         0.5)},
    "",
    {}};

/// The fields of a section: `head` (the project's own), then each table's bound fields.
template <class... Tables>
std::vector<Field> section(std::vector<Field> head, const Tables&... tables) {
  (..., [&] {
    for (Field& f : fields_of(tables)) head.push_back(std::move(f));
  }());
  return head;
}

/// solver.mode's documentation: every strategy of the registry with what it does.
std::string mode_doc() {
  std::string doc = "solver strategy (see docs/ARCHITECTURE.md) — ";
  for (const StrategyInfo& s : solver_registry()) doc += s.name + ": " + s.description + "; ";
  return doc + kAutoSolver +
         ": direct, mixed or (a body partitioned) feti, whichever the partition table's cost model predicts cheapest "
         "(summary.json's solver.auto says why)";
}

const ObjectSchema& solver_schema() {
  static const ObjectSchema s{
      "solver",
      "Linear solver settings.",
      section({flag(def(choice("mode", solver_mode_names(), "", mode_doc()), "direct"), "solver"),
               [] {
                 Field f = flag(str("update",
                                    "Newton: which groups get a new tangent and factor at each iteration — always "
                                    "(Mixed I / DD-I) or selective[:TOL] (Mixed II / DD-II: a group keeps its factor "
                                    "while ‖r_g‖ ≤ TOL ‖r‖; TOL 0.01 by default)"),
                                "update");
                 f.default_value = to_string(UpdateSetting{});
                 f.check = [](const json& v) -> std::string {
                   try {
                     parse_update(v.get<std::string>());
                     return "";
                   } catch (const std::invalid_argument& e) {
                     return e.what();
                   }
                 };
                 return f;
               }()},
              solver_option_fields()),
      "",
      {}};
  return s;
}

const ObjectSchema& analysis_schema() {
  static const ObjectSchema s{
      "analysis",
      "How the loads are applied: in N increments, each with every load and prescribed displacement times its load "
      "factor. `linear` solves the same stiffness at every increment (frictionless contact makes the sequence "
      "meaningful: each increment's active set starts from the previous one's); `newton` iterates on the residual "
      "with the consistent tangent (plasticity; the frictionless active set updated at every iteration) and cuts a "
      "step that does not converge in half. The type is `newton` when a material is plastic and none is given.",
      section({[] {
                 std::vector<std::string> types{"auto"};
                 for (const std::string& n : analysis_names()) types.push_back(n);
                 return choice("type", types, "auto",
                               "analysis: auto (newton when a material is plastic, else linear), linear or newton");
               }(),
               choice("contact_search", {"boxes", "all"}, "boxes",
                      "contact search: boxes — a slave node is projected only on master facets whose bounding box is "
                      "within search_distance; all — on every master facet (the exhaustive search, to measure what "
                      "the boxes save)")},
              increment_option_fields(), newton_option_fields()),
      "",
      {}};
  return s;
}

const ObjectSchema kProbe{"probe",
                          "A named point whose nearest node's displacement is reported in summary.json.",
                          {req(str("name", "probe name, unique")), req(vec("at", "length", "position")),
                           str("body", "restrict the search to this body (default: all bodies)")},
                          "",
                          {}};

const ObjectSchema kOutput{"output",
                           "What is written and where (relative paths: to the working directory).",
                           {str("dir", "output directory (default: results/<project name>; --out overrides)"),
                            def(
                                [] {
                                  Field f;
                                  f.name = "vtu";
                                  f.kind = Kind::Boolean;
                                  f.doc = "write result.vtu";
                                  return f;
                                }(),
                                true),
                            choice("increments", {"all", "last"}, "all",
                                   "with analysis.increments > 1: all — results.pvd and one VTU per increment beside "
                                   "result.vtu; last — result.vtu only"),
                            choice("compression", {"lz4", "zlib", "none"}, "lz4",
                                   "how the VTU files' binary arrays are compressed (ParaView reads each): lz4 (fast, "
                                   "about half the size), zlib (smaller, slower to write), none"),
                            [] {
                              Field f;
                              f.name = "fields";
                              f.kind = Kind::ChoiceList;
                              f.choices = output_field_names();
                              f.choices.insert(f.choices.begin(), kAllFields);
                              f.default_value = json::array({kAllFields});
                              f.min_items = 1;
                              f.doc =
                                  "the field arrays written to result.vtu and the increments' VTUs: all, or the names "
                                  "to write (a name writes its point and its cell array; body_id and subdomain_id are "
                                  "always written; a field the model does not carry is not written)";
                              return f;
                            }()},
                           "",
                           {}};

}  // namespace

const ObjectSchema& project_schema() {
  static const ObjectSchema root{
      "project",
      "A rollsim project. Units are consistent and chosen by the user (e.g. mm, N, MPa); the unit column says "
      "which quantity a field carries. 2D models are plane strain of unit thickness.",
      {str("name", "project name (default: the file name without extension)"),
       [] {
         Field f;
         f.name = "dimension";
         f.kind = Kind::Choice;
         f.int_choices = {2, 3};
         f.required = true;
         f.doc = "2 (plane strain) or 3";
         return f;
       }(),
       str("description", "free text"), objects("materials", kMaterial, "materials (a `process` adds its own)"),
       objects("bodies", kBody, "bodies (at least one, or a `process` that generates them)"),
       [] {
         Field f;  // optional, no default: a project without it has no process
         f.name = "process";
         f.kind = Kind::Object;
         f.object = &process_schema();
         f.doc = "a process that generates bodies, contacts and conditions (`type`: rolling, see below)";
         return f;
       }(),
       objects("boundary_conditions", kBC, "supports and loads"), objects("contacts", kContact, "contact pairs"),
       object("analysis", analysis_schema(), "load increments"), object("solver", solver_schema(), "solver settings"),
       objects("probes", kProbe, "reported points"), object("output", kOutput, "outputs"),
       [] {
         Field f = object("heat", heat_schema(), "heat transfer between conducting bodies and to the air");
         f.default_value = json();
         return f;
       }()},
      "",
      {}};
  return root;
}

std::string project_format_markdown() {
  return "# Project file format\n\n"
         "Generated by `rollsim schema` from the schema the validator uses (core/project/ProjectSchema.cpp); "
         "do not edit by hand. Node sets and surfaces are addressed by name: each mesh generator creates the "
         "surfaces listed with it (and node sets of the same names, plus `all`), and `node_sets` adds more.\n\n"
         "Generated sets: `block`: xmin, xmax, ymin, ymax (, zmin, zmax); `plate_with_hole`: left, bottom, right, "
         "top, hole; `annulus`: inner, outer (, start, end for a sector); `cylinder`: inner, outer, ymin, ymax "
         "(, start, end); `round_bar`: xmin, ymin (its symmetry planes), zmin, zmax, outer.\n\n" +
         schema_markdown(project_schema());
}

}  // namespace rollsim
