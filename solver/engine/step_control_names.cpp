#include "solver/engine/step_control_names.hpp"

namespace radx::solver {

std::string step_control_name(const StepControl& c) {
  using K = StepControl::Kind;
  const std::string id = std::to_string(c.user_id);
  switch (c.kind) {
    case K::Interface: return "interface " + id + " (secondary node " + std::to_string(c.node_id) + ")";
    case K::Spring: return "spring " + id;
    case K::Brick: return "brick " + id;
    case K::Tetra: return "tetrahedron " + id;
    case K::Shell: return "shell " + id;
    case K::Shell3: return "3-node shell " + id;
    case K::Truss: return "truss " + id;
    case K::Beam: return "beam " + id;
    case K::Node: return "node " + id + " (/DT/NODA)";
    case K::Imposed: return "/DTIX";
    case K::None: break;
  }
  return "nothing named";
}

std::string step_stop_keyword(StepControl::Kind kind) {
  using K = StepControl::Kind;
  switch (kind) {
    case K::Interface: return "/DT/INTER/STOP";
    case K::Spring: return "/DT/SPRING/STOP";
    case K::Brick:
    case K::Tetra: return "/DT/BRICK/STOP";
    case K::Shell: return "/DT/SHELL/STOP";
    case K::Shell3: return "/DT/SH_3N/STOP";
    default: return "/DT";
  }
}

}  // namespace radx::solver
