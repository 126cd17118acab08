// Sensors of the run: the state of every /SENSOR of the model, updated once per cycle (OpenRadioss engine
// tools/sensor/sensor_time.F, sensor_init.F; docs/keywords.md /SENSOR/TIME).
//
// /SENSOR/TIME (Tdelay, Tstop): off at the start. Checked once before cycle 0 with (t, dt) = (0, 0), then at
// every cycle once its step is known (t = t_n, dt = t_{n+1} - t_n, after the forces and before the kinematic
// conditions, as Radioss's resol.F):
//   off -> on   when t + dt >= Tdelay; its activation time is Tdelay itself, not the cycle's time;
//   on  -> off  when t + dt >= Tstop (a later check); it never switches on again.
//
// What a sensor drives (OpenRadioss loads/general/force.F90, grav/gravit.F, impvel/fixvel.F,
// inivel/inivel_start.F90, interfaces/intsort/inttri.F, rbody/rbyonf.F) sees the time origin T = the
// activation time (model::kNever while the sensor is off) and the local time tau = t - T:
//   /CLOAD, /PLOAD, /GRAV, /IMPVEL, /IMPDISP act only for tau >= 0 and read their function at tau, so the
//     function's time origin is the activation; before it, and after the sensor switches off, nothing acts;
//   /INIVEL sets its velocity at the first cycle with t >= T (Tstart 0), or >= min(Tstart, T);
//   /INTER/TYPE7 acts for t >= max(Tstart, T) and t < Tstop;
//   /RBODY is rigid until the sensor switches on, and released 2 cycles after
//   (solver/conditions/rigid_body.hpp).
// No allocation in update() unless a sensor switches.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/model/model.hpp"

namespace radx::solver {

class Sensors {
 public:
  explicit Sensors(const model::Model& m);

  // The check of the cycle at time t with step dt (see above).
  void update(double t, double dt);

  // Per model sensor (model.sensors order): its activation time, model::kNever while it is off. The view
  // stays valid for the life of the object.
  [[nodiscard]] std::span<const double> starts() const { return start_; }
  [[nodiscard]] bool empty() const { return start_.empty(); }

  // One line per sensor that switched since the last call, e.g. "SENSOR (TIME) 5 ACTIVATED AT TIME
  // 1.0000E-03" (Radioss's words); taken (emptied) by the call.
  std::vector<std::string> take_messages();

 private:
  enum class State : std::uint8_t { Waiting, On, Done };
  struct Timer {
    std::int64_t id = 0;
    double t_delay = 0, t_stop = model::kNever;
    State state = State::Waiting;
  };
  std::vector<Timer> timers_;
  std::vector<double> start_;
  std::vector<std::string> messages_;
};

// The time origin of an object driven by sensor `sensor` (dense index into model.sensors, kNone for none):
// 0 without a sensor, else the sensor's activation time (model::kNever while it is off). `starts`:
// Sensors::starts(); it must cover the index (throws std::logic_error otherwise).
inline double time_origin(std::int32_t sensor, std::span<const double> starts) {
  if (sensor == model::kNone) return 0.0;
  if (sensor < 0 || static_cast<std::size_t>(sensor) >= starts.size())
    throw std::logic_error("sensor " + std::to_string(sensor) + ": no sensor state (Sensors::starts) given");
  return starts[static_cast<std::size_t>(sensor)];
}

}  // namespace radx::solver
