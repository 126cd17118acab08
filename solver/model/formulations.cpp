#include "solver/model/formulations.hpp"

namespace radx::model {

namespace {
std::string unnamed(int v) {
  return v < 0 ? "automatic choice" : "formulation " + std::to_string(v);
}
}  // namespace

std::string ishell_name(int v) {
  switch (v) {
    case 1: return "Belytschko-Tsay with viscous and elastic hourglass";
    case 2: return "Belytschko-Tsay with the plain hourglass vector";
    case 3: return "Belytschko-Tsay with elasto-plastic hourglass";
    case 4: return "improved Belytschko-Tsay with warping";
    case 12: return "QBAT, four Gauss points";
    case 24: return "QEPH, physical hourglass";
    default: return unnamed(v);
  }
}

std::string ish3n_name(int v) {
  switch (v) {
    case 1: return "C0 without the second large-rotation term";
    case 2: return "C0";
    case 30: return "DKT18";
    case 31: return "DKT_S3";
    default: return unnamed(v);
  }
}

std::string isolid_name(int v) {
  switch (v) {
    case 1: return "one point, Flanagan-Belytschko viscous hourglass";
    case 2: return "one point, plain hourglass vectors";
    case 12: return "S8 fully integrated (old)";
    case 14: return "HA8, fully integrated";
    case 15: return "HSEPH thick shell";
    case 16: return "20-node quadratic";
    case 17: return "H8C, fully integrated with constant pressure";
    case 18: return "H8D, fully integrated";
    case 24: return "HEPH, physical hourglass";
    default: return unnamed(v);
  }
}

bool runs_ishell(int v) {
  return v == 1 || v == 4 || v == 12 || v == 24;
}
bool runs_ish3n(int v) {
  return v == 1 || v == 2;
}
bool runs_isolid(int v) {
  return v == 1 || v == 2 || v == 24 || v == 12 || v == 14 || v == 17 || v == 18;
}

}  // namespace radx::model
