#include "solver/conditions/sensors.hpp"

#include <cstdio>

namespace radx::solver {

namespace {

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4E", v);
  return buf;
}

}  // namespace

Sensors::Sensors(const model::Model& m) {
  for (const auto& s : m.sensors) {
    if (s.type != model::SensorType::Time)
      throw std::runtime_error("/SENSOR/" + std::to_string(s.id) + ": only /SENSOR/TIME is supported");
    timers_.push_back(Timer{s.id, s.t_delay, s.t_stop, State::Waiting});
  }
  start_.assign(timers_.size(), model::kNever);
}

void Sensors::update(double t, double dt) {
  const double next = t + dt;
  for (std::size_t k = 0; k < timers_.size(); ++k) {
    auto& s = timers_[k];
    const char* what = nullptr;
    double at = 0;
    if (s.state == State::Waiting && next >= s.t_delay) {
      s.state = State::On;
      start_[k] = s.t_delay;
      what = "ACTIVATED";
      at = s.t_delay;
    } else if (s.state == State::On && next >= s.t_stop) {
      s.state = State::Done;
      start_[k] = model::kNever;
      what = "DEACTIVATED";
      at = s.t_stop;
    }
    if (what)
      messages_.push_back("SENSOR (TIME) " + std::to_string(s.id) + " " + what + " AT TIME " + sci(at));
  }
}

std::vector<std::string> Sensors::take_messages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

}  // namespace radx::solver
