// Time-history values (docs/theory/results-format.md section 7): the global variables in Radioss's order and
// the values of each /TH group of the model, sampled from the running engine on a full report cycle.
//
// Global, in this order: IE internal energy, KE kinetic (translational), XMOM YMOM ZMOM momentum, MASS,
// DT time step, RKE rotational kinetic energy, EXTW external work, SE spring energy (0: no springs), CE
// contact energy (elastic + friction + damping + Lagrange), HE hourglass energy, CE_ELAST, CE_FRIC,
// CE_DAMP, PW plastic work, DMAS added mass, DMAS_PCT added mass in % of the initial mass.
//
// Per part (and subset, over its parts and child subsets): IE and HE sum the element energies of the
// part; KE, XMOM.. and MASS share each node's mass among the parts of its elements in proportion to
// their lumped-mass contributions (a node between two parts counts for both, in shares); ERODED is the
// initial mass of the part's deleted elements; HEAT is 0 (radx has no thermal analysis).
// Per node: D = x - x0, V at the full step v^{n-1/2} + dt1/2 a^n, A = a^n, VR, AR the angular velocity
// and acceleration, DR = 0 (rotations are not integrated as angles), X Y Z current, REAC = m a - f and
// REACXX.. = I aw - M (what kinematic conditions add); for a node listed with a skew, each of these vectors
// on the skew's axes of the sampled cycle (X Y Z the position's components on them, as OpenRadioss thnod.F:
// not measured from the skew's origin).
// Per rigid wall: FN, FT the normal and tangential force of the last cycle.
// Per interface: FN, FT the sums over the secondary nodes of the normal (with damping) and friction forces,
// as interval means (below); CE_ELAST, CE_FRIC, CE_DAMP the booked contact energies.
// Per 4-node shell (/TH/SHEL) and per 3-node shell (/TH/SH3N): F1 F2 F12 = t x mean stress (membrane forces
// per unit length, element frame: the triangle's x axis along n1 -> n2), M1 M2 M12 = t^2 sum m_i sigma_i
// (moments per unit length), IEM = the element's internal energy (radx does not split membrane and bending
// energy), IEB = 0, OFF the kill factor, EMIN EMAX = 0 (strains are not kept).
// Per brick (/TH/BRIC), the one integration point: OFF the kill factor; SX SY SZ SXY SYZ SXZ the Cauchy
// stress, global axes, without the bulk viscosity; IE = internal energy / initial volume (energy density, as
// OpenRadioss's EINT); DENS = rho0 V0 / V; BULK = q, the bulk-viscosity pressure (> 0 in compression);
// VOL = V; PLAS the plastic strain; PLSR the strain-rate measure of hex8_fb.cpp; VX VY VZ the mean of the
// eight nodes' velocities at the full step; TEMP = 0 (no thermal analysis).
// Per spring (/TH/SPRING): OFF 1 alive, 0 broken; FX the axial force (> 0 in tension), LX the elongation
// L - L0, IE the work of the spring force; the other names are 0 for TYPE4 springs.
// Per rigid body (/TH/RBODY): FX FY FZ, MX MY MZ the force and the moment about the main node that the body
// receives at its secondary nodes in the last cycle (elements, contact, loads on them; what acts on the
// main node itself, its loads and the body's weight, is not in them: OpenRadioss rgbodfp.F); RX RY RZ = sum
// of omega dt since t = 0 (global components of the rotation, exact for a rotation about a fixed axis); FXI..
// MZI = 0 (TYPE14 and TYPE15 interfaces do not exist in radx); X Y Z, DX DY DZ, VX.., AX.., VRX.., ARX.. the
// main node's, as for /TH/NODE; MASS the body's mass; IXX IYY IZZ IXY IYZ IZX the inertia tensor in use,
// global axes, about the main node, at the current orientation; STATUS 1 for a body formed in this run, 0 for
// one switched off by /RBODY/OFF (its forces, rotation and inertia are then 0 and its main node is a free
// node). The starter lists the variables written as 0 (deck check warning) where a deck asks for them.
// Per section (/TH/SECTIO, solver/outputs/section_cut.cpp): FNX FNY FNZ = (F . n) n and FTX FTY FTZ = F - (F
// . n) n, global components, where F is the force the section's elements apply to its nodes; M1 M2 M3 and F1
// F2 F3 the moment about the centre and the force on the section's axes; MX MY MZ the moment on the global
// axes (all interval means, below); CX CY CZ the centre on the sampled cycle.
//
// Interval means. An interface's forces and a section's forces and moments change every cycle (a contact
// force rings at the contact stiffness' frequency), so a value sampled on one cycle per row is noise. Like
// OpenRadioss, which sums the impulse F dt of every cycle and writes it for its readers to divide by the
// output interval, radx writes the impulse over the interval divided by the interval, for a row at t_k:
//     F_k = (1 / (t_k - t_{k-1})) sum_{cycles m in (t_{k-1}, t_k]} (F^{m-1} + F^m) / 2 (t_m - t_{m-1})
// the trapezoid rule over the cycles' values F^m (F at t_m). Its interval is exactly (t_{k-1}, t_k], so a
// constant force gives itself, a force linear in time gives its value at mid-interval, and the impulses
// F_k (t_k - t_{k-1}) add up to the momentum change of the full-step velocities v^{m-1/2} + dt1/2 a^m that
// /TH/NODE and /TH/PART write (OpenRadioss's sum of F dt12 runs half a step past t_k). The first row, which
// has no interval, holds the value of its cycle. Every row after it holds the mean over the time since the
// previous row, whatever that time (the last row, on the end time, often has a shorter interval; with
// /TFILE 0, a row every cycle, each row is the mean of two consecutive cycles). The value of the sampled
// cycle itself stays available as the variable <VAR>_INST (FNX_INST, M1_INST, ...), written after the deck's
// variables for each averaged one.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "solver/engine/explicit_engine.hpp"
#include "solver/outputs/section_cut.hpp"

namespace radx::solver {

// Physical dimension as exponents of mass, length and time (for unit labels).
struct Dim {
  int mass = 0, length = 0, time = 0;
};

struct ThVariableInfo {
  std::string name;
  Dim dim;
};

const std::vector<ThVariableInfo>& global_th_variables();
Dim th_variable_dim(model::ThKind kind, const std::string& name);

// Values of the global variables for report `r` (a full report).
void global_th_values(const ExplicitEngine& e, const CycleReport& r, std::span<double> out);

// One /TH group: objects x variables values, object-major.
class ThGroupSampler {
 public:
  ThGroupSampler(const ExplicitEngine& e, const model::TimeHistoryGroup& g);
  [[nodiscard]] std::size_t size() const { return objects_.size() * variables_.size(); }
  // The variables written per object: the deck's, then <VAR>_INST for each averaged one.
  [[nodiscard]] const std::vector<std::string>& variables() const { return variables_; }
  // Whether the group has interval means (interfaces and sections with a force or moment variable): then
  // accumulate must see every cycle.
  [[nodiscard]] bool averages() const { return !averaged_.empty(); }
  // Every cycle, before a row of that cycle is sampled: adds the trapezoid of the cycle's step.
  void accumulate(const ExplicitEngine& e, const CycleReport& r);
  // A row: the instantaneous values, the interval means in place of the averaged variables (the interval
  // then starts anew at r.time). A cycle not accumulated yet is accumulated first.
  void sample(const ExplicitEngine& e, const CycleReport& r, std::span<double> out);

 private:
  // The output row of a sample: put(object, variable, value) writes a variable the group asks for and ignores
  // the others.
  struct ThPut {
    std::span<double> out;
    const std::vector<std::string>& variables;
    void operator()(std::size_t obj, const std::string& name, double value) const;
  };
  void sample_nodes(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_parts(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_rigid_walls(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_interfaces(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_shells(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_bricks(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_brick20(const ExplicitEngine& e, const CycleReport& r, const ThPut& put, std::size_t o) const;
  void sample_rigid_bodies(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_sections(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_springs(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_trusses(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_beams(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  void sample_accelerometers(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const;
  // The values of the cycle, every variable as sampled (no means).
  void sample_cycle(const ExplicitEngine& e, const CycleReport& r, std::span<double> out) const;

  model::ThKind kind_;
  std::vector<std::int32_t> objects_;
  std::vector<std::string> variables_;
  // Parts and subsets: for each part, (node, mass share) of its nodes; for each object, its parts.
  std::vector<std::vector<std::pair<std::int32_t, double>>> part_nodes_;
  std::vector<std::vector<std::int32_t>> object_parts_;
  // Elements: for each object, its (group, slot) in the engine's element groups ({-1, -1}: in none).
  // Rigid bodies: for each object, its index in the bodies formed in this run (-1: switched off).
  std::vector<std::pair<int, int>> slots_;
  std::vector<std::uint8_t>
      quadratic_;  // /TH/BRIC: 1 for an object that is a 20-node brick (slot in bricks20)
  std::vector<int> bodies_;
  std::vector<std::int32_t> skews_;   // nodes: the dense skew index of each object (kNone: global axes)
  std::vector<SectionSum> sections_;  // sections: one per object
  // Interval means: for each averaged variable, its column and its <VAR>_INST column.
  std::vector<std::pair<std::size_t, std::size_t>> averaged_;
  std::vector<double> last_;      // the values of the last cycle accumulated (object-major, as a row)
  std::vector<double> integral_;  // sum of the trapezoids since the last row, per value
  std::vector<double> cycle_;     // scratch: the values of the cycle being accumulated
  double last_time_ = 0;          // of the last cycle accumulated
  double row_time_ = 0;           // of the last row
  bool accumulated_ = false, sampled_ = false;
};

}  // namespace radx::solver
