// What the engine deck asks for (docs/theory/deck-format.md section 3), resolved: defaults applied, times in
// work units. Built by the parser from the engine deck; read by the engine. Depends on nothing of ours.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radx::model {

// /DT/<family>/<action>: a scale on the family's step and a minimum with an action when it is reached.
enum class DtAction : std::uint8_t { None, Stop, Delete, Constant, AddMass, Lagrange };

struct DtControl {
  double scale = 0.9;  // Tscale (0 -> 0.9)
  double t_min = 0.0;  // Tmin (0 -> no minimum)
  DtAction action = DtAction::None;
  bool given = false;
};

struct RunControls {
  std::string run_name;
  int run_number = 1;
  double t_stop = 0;  // /RUN end time

  // Outputs.
  double anim_start = 0, anim_dt = 0, anim_stop = 1e20;  // /ANIM/DT (anim_dt 0: no states but first/last)
  std::vector<std::string> anim_elem, anim_vect, anim_tens, anim_noda;  // names as written, upper case
  double th_dt = 1e30;                                                  // /TFILE (0: every cycle)
  int print_every = 100;                                                // |n| of /PRINT/n
  bool print_stdout = true;                                             // negative n also prints to stdout
  int print_header_every = 0;

  // Time step.
  DtControl global;                     // /DT: element step scale and minimum (Tmin reached: stop)
  DtControl nodal;                      // /DT/NODA/CST: mass added below Tmin
  double nodal_max_added_mass_pct = 0;  // /DT/NODA/CST third value: stop beyond it (0: no limit)
  DtControl brick, shell, shell3;       // /DT/BRICK|SHELL|SH_3N/CST: small-strain switch at Tmin; /STOP
  DtControl spring;                     // /DT/SPRING/STOP
  DtControl inter;                      // /DT/INTER/CST, /DEL, /LAG, /STOP
  double dt_initial = 0;                // /DTIX DT_ini: the first step is at most this (0: no bound)
  double dt_max = 1e30;                 // /DTIX DT_max: no step above it

  // /STOP.
  double stop_energy_error_pct = 1e30, stop_mass_error = 1e30, stop_nodal_mass_error = 1e30;
  bool stop_writes_th = false, stop_writes_anim = false, stop_positive_error_only = false;

  // /RBODY/ON and /RBODY/OFF: user ids switched at the start of this run.
  std::vector<std::int64_t> rbody_on, rbody_off;
};

}  // namespace radx::model
