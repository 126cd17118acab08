// Section cuts (/SECT): the force and moment that a section's elements apply to its nodes, in the section's
// frame. The equations are in section_cut.cpp; the definition of the frame and centre in model::Section.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

using Vec3 = std::array<double, 3>;

// One evaluation of a cut, global components unless said otherwise.
struct SectionCut {
  Vec3 force{};                // F = sum of the element forces at the cut's nodes
  Vec3 moment{};               // M about `centre` (node offsets x F, plus the shell nodal moments)
  Vec3 centre{};               // moment reference point C
  Vec3 normal{};               // unit section normal n
  std::array<Vec3, 3> axes{};  // frame axes e1 e2 e3 (global axes for Iframe >= 10)
  Vec3 normal_force{};         // (F . n) n
  Vec3 tangential_force{};     // F - (F . n) n
  Vec3 local_force{};          // F . e_k
  Vec3 local_moment{};         // M . e_k
};

// The elements of one section, found once in the engine's element groups (they do not change during a
// run), with the corners that lie on the cut. Read-only on the groups and the nodes.
class SectionSum {
 public:
  SectionSum(const model::Section& s, const ElementGroups& groups);
  [[nodiscard]] SectionCut evaluate(const NodeState& nodes, const ElementGroups& groups) const;

 private:
  enum class Kind : std::uint8_t { Shell, Brick, Truss, Beam };
  struct Term {
    Kind kind = Kind::Shell;
    int group = 0, slot = 0;
    std::uint8_t corners = 0;  // bit q set: corner q of the element is a node of the cut
  };
  std::vector<Term> terms_;
  std::vector<std::int32_t> nodes_;
  std::int32_t n1_, n2_, n3_;
  int iframe_;
};

}  // namespace radx::solver
