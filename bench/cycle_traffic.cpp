// Bytes moved per element-cycle: the memory traffic of one engine cycle, summed from the arrays
// the engine actually holds for a model (the starter's model file and the engine deck), so the figure follows
// the data layout as it changes. Prints each pass of the cycle, each array it reads or writes and its bytes,
// the total per element-cycle and, given the measured bandwidth (bench/stream_bandwidth.sh, triad) and the
// measured cost in microseconds per element-cycle, the traffic limit and the ratio of the cost to it.
//
// The count (the compulsory traffic of a cycle whose arrays do not fit in cache):
//   * an array a pass only reads counts its bytes once; one it reads and writes back, twice; one it only
//     writes, once (the write-allocate read of a store miss is not counted, as STREAM does not count it);
//   * the per-element arrays of a group count rows x count x element size (`rows` from the array's length,
//     so 5 thickness points give 25 stress rows); the arrays a kernel reads only under a condition (the
//     failure damage, law 27's crack state, the small-strain geometry after a /DT/.../CST switch, the
//     co-rotational frame) count only when that condition holds for the group;
//   * the node gather of an element pass counts each node array once per node the family touches (perfect
//     reuse of a node's values by the neighbouring elements of a block); the same gather without any reuse
//     (each element reading its own nodes' values) is printed as an upper bound;
//   * each group's nodal-force buffer is read back once and added to the nodes' element sums ([node][6]) in
//     the element stage, right after the group (counted although it is often still in cache then); the
//     assembly reads the sums, clears them and writes the node forces;
//   * contact (search and forces) is left out: its share of the wall time is reported separately; so are the
//     energy sums, which run on report cycles only (/PRINT), and the boundary conditions (edge nodes only).
// Kernels counted array by array: the Belytschko-Tsay shell (shell_bt4.cpp, Ishell 1 and 4) and the one-point
// brick (hex8_fb.cpp, Isolid 1 and 2). Other kernels count every array their group allocated as read and
// written (an upper bound), and the listing says so.
//
// Usage: radx_bench_traffic ENGINE_DECK MODEL_FILE [--bandwidth GB/s] [--us US_PER_ELEMENT_CYCLE]
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "io/hdf5/model_file.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/reading/diagnostics.hpp"
#include "solver/engine/explicit_engine.hpp"

namespace {

using radx::solver::kGroupSize;

enum class Mode { Read, Write, ReadWrite };

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::Read: return "r";
    case Mode::Write: return "w";
    case Mode::ReadWrite: return "rw";
  }
  return "?";
}

double mode_factor(Mode m) {
  return m == Mode::ReadWrite ? 2.0 : 1.0;
}

// Bytes of one array over the pass: per-element rows x elements x element size, times the mode factor.
struct Line {
  std::string pass, array;
  Mode mode;
  double bytes;
};

struct Ledger {
  std::vector<Line> lines;
  void add(const std::string& pass, const std::string& array, Mode mode, double bytes) {
    if (bytes <= 0) return;
    for (auto& l : lines)
      if (l.pass == pass && l.array == array && l.mode == mode) {
        l.bytes += bytes;
        return;
      }
    lines.push_back({pass, array, mode, bytes});
  }
  template <class V>
  void group_array(const std::string& pass, const std::string& name, const V& v, int count, Mode mode) {
    if (v.empty()) return;
    const double rows = static_cast<double>(v.size()) / kGroupSize;
    add(pass, name, mode, mode_factor(mode) * rows * count * sizeof(typename V::value_type));
  }
  [[nodiscard]] double total(const std::string& prefix = "") const {
    double t = 0;
    for (const auto& l : lines)
      if (l.pass.rfind(prefix, 0) == 0) t += l.bytes;
    return t;
  }
};

// What the element passes leave for the gather and the report: the nodes each family touches, the
// element-node slots, the gather without reuse, and the notes on what is not counted exactly.
struct Tally {
  std::set<std::int32_t> shell_nodes, solid_nodes;
  double slots = 0, gather_no_reuse = 0;
  std::vector<std::string> notes;
};

constexpr double d = sizeof(double);

// The shell groups' arrays, as the Belytschko-Tsay kernel reads and writes them; any other kernel's arrays
// all read and written.
void count_shell_groups(const radx::solver::ExplicitEngine& engine, const radx::model::RunControls& controls,
                        Ledger& L, Tally& T) {
  using namespace radx;
  const auto& mats = engine.materials();
  for (const auto& g : engine.groups().shells) {
    const int n = g.count;
    const auto& mat = mats[static_cast<std::size_t>(g.material)];
    const int npe = g.triangle ? 3 : 4;
    for (int k = 0; k < npe; ++k)
      for (int i = 0; i < n; ++i) T.shell_nodes.insert(g.conn[static_cast<std::size_t>(k * kGroupSize + i)]);
    T.slots += static_cast<double>(npe) * n;
    T.gather_no_reuse += static_cast<double>(npe) * n * 9 * d;
    const std::string p = "shell elements";
    if (g.kernel != solver::ShellKernel::Bt4) {
      T.notes.push_back(
          "a shell group not in Belytschko-Tsay: every allocated array counted as read and written");
      for (const auto* v :
           {&g.t0,   &g.thick,      &g.area0,    &g.off,   &g.sig,       &g.eps_p,   &g.res,
            &g.dmg,  &g.fail_scale, &g.brit,     &g.hg,    &g.e_int,     &g.e_hg,    &g.w_plastic,
            &g.rate, &g.dt,         &g.dt_fixed, &g.small, &g.ref_local, &g.k_nodal, &g.nodal_force})
        L.group_array(p, "other shell state", *v, n, Mode::ReadWrite);
      L.group_array(p, "conn", g.conn, n, Mode::Read);
      continue;
    }
    L.group_array(p, "conn [4] int32", g.conn, n, Mode::Read);
    L.group_array(p, "t0", g.t0, n, Mode::Read);
    L.group_array(p, "thick", g.thick, n, Mode::ReadWrite);
    L.group_array(p, "off", g.off, n, Mode::Read);
    L.group_array(p, "dt_fixed", g.dt_fixed, n, Mode::Read);
    L.group_array(p, "small", g.small, n, Mode::Read);
    L.group_array(p, "sig [points][5]", g.sig, n, Mode::ReadWrite);
    L.group_array(p, "eps_p [points]", g.eps_p, n, Mode::ReadWrite);
    if (g.props.n_points > 0) L.group_array(p, "res [8] (old resultants)", g.res, n, Mode::ReadWrite);
    if (mat.fail.on) {
      L.group_array(p, "dmg [points]", g.dmg, n, Mode::ReadWrite);
      L.group_array(p, "fail_scale", g.fail_scale, n, Mode::Read);
    }
    if (mat.law == model::MaterialLaw::PlasBrit)
      L.group_array(p, "brit (law 27)", g.brit, n, Mode::ReadWrite);
    if (g.props.ismstr == 1 || controls.shell.action == model::DtAction::Constant)
      L.group_array(p, "ref_local (small strain)", g.ref_local, n, Mode::Read);
    L.group_array(p, "hg [3]", g.hg, n, Mode::ReadWrite);
    for (const auto& [name, v] :
         {std::pair{"e_int", &g.e_int}, {"e_hg", &g.e_hg}, {"w_plastic", &g.w_plastic}, {"rate", &g.rate}})
      L.group_array(p, name, *v, n, Mode::ReadWrite);
    L.group_array(p, "dt", g.dt, n, Mode::Write);
    L.group_array(p, "k_nodal", g.k_nodal, n, Mode::Write);
    L.group_array(p, "nodal_force [4][6]", g.nodal_force, n, Mode::Write);
  }
}

// The one-point brick groups' arrays, as their kernel reads and writes them; any other kernel's arrays all
// read and written.
void count_brick_groups(const radx::solver::ExplicitEngine& engine, const radx::model::RunControls& controls,
                        Ledger& L, Tally& T) {
  using namespace radx;
  for (const auto& g : engine.groups().bricks) {
    const int n = g.count;
    for (int k = 0; k < 8; ++k)
      for (int i = 0; i < n; ++i) T.solid_nodes.insert(g.conn[static_cast<std::size_t>(k * kGroupSize + i)]);
    T.slots += 8.0 * n;
    T.gather_no_reuse += 8.0 * n * 6 * d;
    const std::string p = "brick elements";
    if (solver::brick_kernel(g) != solver::BrickKernel::OnePoint) {
      T.notes.push_back("a brick group not one-point: every allocated array counted as read and written");
      for (const auto* v :
           {&g.sig_p,       &g.eps_p_p,   &g.dmg_p,     &g.vol0_p, &g.vol0,     &g.vol,   &g.rho,
            &g.off,         &g.sig,       &g.eps_p,     &g.dmg,    &g.q,        &g.e_int, &g.e_hg,
            &g.hg_force,    &g.w_plastic, &g.rate,      &g.dt,     &g.dt_fixed, &g.x_ref, &g.k_nodal,
            &g.nodal_force, &g.frame,     &g.hg_stress, &g.w_hg,   &g.b_ref,    &g.foam})
        L.group_array(p, "other brick state", *v, n, Mode::ReadWrite);
      L.group_array(p, "conn [8] int32", g.conn, n, Mode::Read);
      continue;
    }
    L.group_array(p, "conn [8] int32", g.conn, n, Mode::Read);
    L.group_array(p, "off", g.off, n, Mode::ReadWrite);
    L.group_array(p, "vol0", g.vol0, n, Mode::Read);
    L.group_array(p, "vol", g.vol, n, Mode::ReadWrite);
    L.group_array(p, "dt_fixed", g.dt_fixed, n, Mode::Read);
    L.group_array(p, "small uint8", g.small, n, Mode::Read);
    if (controls.brick.action == model::DtAction::Constant)
      L.group_array(p, "x_ref (small strain)", g.x_ref, n, Mode::Read);
    L.group_array(p, "sig [6]", g.sig, n, Mode::ReadWrite);
    for (const auto& [name, v] : {std::pair{"rate", &g.rate},
                                  {"eps_p", &g.eps_p},
                                  {"dmg", &g.dmg},
                                  {"q", &g.q},
                                  {"e_int", &g.e_int},
                                  {"e_hg", &g.e_hg},
                                  {"w_plastic", &g.w_plastic}})
      L.group_array(p, name, *v, n, Mode::ReadWrite);
    L.group_array(p, "hg_force [4][3]", g.hg_force, n, Mode::ReadWrite);
    if (solver::brick_corotational(g)) L.group_array(p, "frame [9]", g.frame, n, Mode::ReadWrite);
    L.group_array(p, "b_ref (total-strain laws)", g.b_ref, n, Mode::Read);
    L.group_array(p, "foam (law 70)", g.foam, n, Mode::ReadWrite);
    L.group_array(p, "rho", g.rho, n, Mode::Write);
    L.group_array(p, "dt", g.dt, n, Mode::Write);
    L.group_array(p, "k_nodal", g.k_nodal, n, Mode::Write);
    L.group_array(p, "nodal_force [8][3]", g.nodal_force, n, Mode::Write);
  }
}

// The node gather of the element passes (each touched node's arrays once), the element sums and the node
// passes.
void count_node_passes(const radx::solver::ExplicitEngine& engine, const Tally& T, Ledger& L) {
  const auto& nodes = engine.nodes();
  const double ns = static_cast<double>(T.shell_nodes.size());
  std::set<std::int32_t> all_elem_nodes = T.shell_nodes;
  all_elem_nodes.insert(T.solid_nodes.begin(), T.solid_nodes.end());
  const double ne = static_cast<double>(all_elem_nodes.size());
  L.add("element gather", "x y z vx vy vz (element nodes)", Mode::Read, 6 * d * ne);
  L.add("element gather", "wx wy wz (shell nodes)", Mode::Read, 3 * d * ns);

  // Node passes: the engine's three (solver/engine/explicit_engine.cpp): the assembly, with a = f / m in the
  // same pass when the engine fuses them, the accelerations on their own otherwise, and the integration,
  // which also zeroes the next cycle's external forces and moments.
  const double nn = static_cast<double>(nodes.n);
  const bool fused = engine.fuses_accelerations();
  const std::string assembly = fused ? "node: assembly + accelerations" : "node: assembly";
  // The element stage adds each group's nodal-force buffer (just written) to the nodes' sums, in group order.
  const std::string sums = "element sums";
  for (const auto& g : engine.groups().shells)
    L.group_array(sums, "group nodal_force (read back)", g.nodal_force, g.count, Mode::Read);
  for (const auto& g : engine.groups().bricks)
    L.group_array(sums, "group nodal_force (read back)", g.nodal_force, g.count, Mode::Read);
  L.add(sums, "element_sums [node][6] (added to)", Mode::ReadWrite, 2 * 6 * d * nn);
  L.add(assembly, "element_sums [node][6] (read, then cleared)", Mode::ReadWrite, 2 * 6 * d * nn);
  L.add(assembly, "fx_ext fy_ext fz_ext", Mode::Read, 3 * d * nn);
  L.add(assembly, "fx fy fz", Mode::Write, 3 * d * nn);
  L.add(assembly, "mx my mz", Mode::ReadWrite, 2 * 3 * d * nn);
  if (fused) {
    L.add(assembly, "mass inertia", Mode::Read, 2 * d * nn);
    L.add(assembly, "ax ay az awx awy awz", Mode::Write, 6 * d * nn);
  } else {
    L.add("node: accelerations", "mass inertia fx fy fz mx my mz", Mode::Read, 8 * d * nn);
    L.add("node: accelerations", "ax ay az awx awy awz", Mode::Write, 6 * d * nn);
  }
  // The time-step vote runs in the element pass right after each group's forces: dt and dt_fixed are still in
  // cache there, and the model's user id is read for the controlling element alone (not counted).
  L.add("node: integration", "ax ay az awx awy awz", Mode::Read, 6 * d * nn);
  L.add("node: integration", "vx vy vz wx wy wz", Mode::ReadWrite, 2 * 6 * d * nn);
  L.add("node: integration", "x y z", Mode::ReadWrite, 2 * 3 * d * nn);
  L.add("node: integration", "fx_ext fy_ext fz_ext mx my mz (zeroed for the next cycle)", Mode::Write,
        6 * d * nn);
}

// The ledger, its totals per family and per element-cycle, and the traffic limit at the measured bandwidth.
void print_report(const radx::solver::ExplicitEngine& engine, const Ledger& L, const Tally& T,
                  double bandwidth, double us) {
  const double nn = static_cast<double>(engine.nodes().n);
  const double ns = static_cast<double>(T.shell_nodes.size());
  const double elements = static_cast<double>(engine.element_count());
  std::printf(
      "model: %.0f elements (%zu shell groups, %zu brick groups), %.0f nodes (%.0f of shells), "
      "%.0f element-node slots\n\n",
      elements, engine.groups().shells.size(), engine.groups().bricks.size(), nn, ns, T.slots);
  std::printf("| pass | arrays | access | MB per cycle | bytes per element-cycle |\n");
  std::printf("|------|--------|:------:|-------------:|------------------------:|\n");
  for (const auto& l : L.lines)
    std::printf("| %s | %s | %s | %.2f | %.1f |\n", l.pass.c_str(), l.array.c_str(), mode_name(l.mode),
                l.bytes * 1e-6, l.bytes / elements);
  const double total = L.total();
  const double shell_b = L.total("shell elements"), brick_b = L.total("brick elements");
  const double gather = L.total("element gather"), node_b = L.total("node:"),
               sums_b = L.total("element sums");
  std::printf(
      "\nper element-cycle: shell state %.0f B, brick state %.0f B, node gather %.0f B, element sums %.0f B, "
      "node passes %.0f B\n",
      shell_b / elements, brick_b / elements, gather / elements, sums_b / elements, node_b / elements);
  std::printf("bytes per element-cycle: %.0f (%.1f MB per cycle)\n", total / elements, total * 1e-6);
  std::printf("upper bound with a gather that reuses nothing (each element reads its own nodes): %.0f\n",
              (total - gather + T.gather_no_reuse) / elements);
  for (const auto& n : T.notes) std::printf("note: %s\n", n.c_str());
  if (bandwidth > 0) {
    const double limit_us = total / elements / (bandwidth * 1e3);
    std::printf("traffic limit at %.2f GB/s: %.4f us per element-cycle\n", bandwidth, limit_us);
    if (us > 0)
      std::printf("measured %.4f us per element-cycle: %.2f x the traffic limit\n", us, us / limit_us);
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace radx;
  if (argc < 3) {
    std::fprintf(
        stderr,
        "usage: radx_bench_traffic ENGINE_DECK MODEL_FILE [--bandwidth GB/s] [--us US_PER_ELEMENT_CYCLE]\n");
    return 2;
  }
  double bandwidth = 0, us = 0;
  for (int a = 3; a + 1 < argc; a += 2) {
    if (std::strcmp(argv[a], "--bandwidth") == 0)
      bandwidth = std::atof(argv[a + 1]);
    else if (std::strcmp(argv[a], "--us") == 0)
      us = std::atof(argv[a + 1]);
    else {
      std::fprintf(stderr, "radx_bench_traffic: unknown option %s\n", argv[a]);
      return 2;
    }
  }
  Diagnostics diags;
  const model::RunControls controls = read_run_controls(argv[1], diags);
  if (diags.has_errors()) {
    diags.print(std::cerr);
    return 1;
  }
  model::Model model;
  std::string error;
  if (!io::read_model_file(argv[2], model, error)) {
    std::cerr << argv[2] << ": " << error << '\n';
    return 1;
  }
  const solver::ExplicitEngine engine(model, controls, solver::EngineOptions(1));
  Ledger L;
  Tally T;
  count_shell_groups(engine, controls, L, T);
  count_brick_groups(engine, controls, L, T);
  if (!engine.groups().tetras.empty() || !engine.groups().springs.empty())
    T.notes.push_back("tetrahedra and springs are not counted");
  count_node_passes(engine, T, L);
  print_report(engine, L, T, bandwidth, us);
  return 0;
}
