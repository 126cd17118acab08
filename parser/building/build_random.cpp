// /RANDOM and /RANDOM/GRNOD: a random perturbation of the initial node coordinates, the usual trigger of
// buckling in crash decks. Each coordinate of each perturbed node, in node order and x, y, z order, moves by
//
//   dx = XALEA r,   r = (I - 32768) / 32768 in [-1, 1),
//   I_{k+1} = (25173 I_k + 13849) mod 65536,   I_0 = trunc(SEED 32768 + 32768) (I_0 = 0 when SEED = 0),
//
// the classic 16-bit linear congruential generator that Radioss uses, so that the same deck perturbs the same
// nodes by the same amounts (node order: the order of the deck, as Radioss numbers them). The first step
// is taken in 32-bit two's-complement arithmetic as Radioss's integers are (a large SEED wraps there); after
// it |I| < 65536 and nothing overflows. One sequence runs through every perturbed node and every group, and
// its seed is the SEED of the first perturbation applied.
//
// Which perturbation applies, as in Radioss: with /RANDOM (all nodes, XALEA > 0) and no /RANDOM/GRNOD, every
// node, by the XALEA of the last such /RANDOM; with /RANDOM/GRNOD only, each group in deck order by its own
// XALEA (a node in two groups moves twice). Radioss applies neither when both kinds are given: radx refuses
// that deck rather than run it unperturbed without a word.
#include <cmath>
#include <cstdint>
#include <limits>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx::detail {

namespace {

class RadiossRandom {
 public:
  explicit RadiossRandom(double seed) {
    if (seed == 0.0) return;
    // A seed beyond 32 bits (or not a number): Radioss's INT on x86 (cvttsd2si) gives the integer
    // indefinite, INT32_MIN; in C++ the conversion would be undefined.
    const double v = seed * 32768.0 + 32768.0;
    state_ = v > -2147483649.0 && v < 2147483648.0 ? static_cast<std::int32_t>(v)
                                                   : std::numeric_limits<std::int32_t>::min();
  }
  double next() {
    // 32-bit wrap of 25173 I + 13849, then Fortran's MOD (the sign of the dividend), as C++'s %.
    const auto wrapped =
        static_cast<std::int32_t>(static_cast<std::uint32_t>(25173) * static_cast<std::uint32_t>(state_) +
                                  static_cast<std::uint32_t>(13849));
    state_ = wrapped % 65536;
    return (static_cast<double>(state_) - 32768.0) / 32768.0;
  }

 private:
  std::int32_t state_ = 0;
};

}  // namespace

void ModelBuilder::apply_random_perturbation() {
  const KeywordRecord* all = nullptr;
  for (const auto* r : deck_.of("/RANDOM"))
    if (r->get_real("XALEA") > 0) all = r;
  std::vector<const KeywordRecord*> groups;
  for (const auto* r : deck_.of("/RANDOM/GRNOD"))
    if (r->get_real("XALEA") > 0) groups.push_back(r);
  if (!all && groups.empty()) return;
  if (all && !groups.empty()) {
    error_at(
        *groups.front(), "XALEA", Diag::InconsistentValues,
        "/RANDOM (all nodes) and /RANDOM/GRNOD are both given: Radioss then perturbs no node at all; keep "
        "one kind (the all-node /RANDOM at line " +
            std::to_string(all->pos.line) + ", or the /RANDOM/GRNOD groups)");
    return;
  }
  auto& x = m_.nodes;
  if (all) {
    const double a = all->get_real("XALEA");
    RadiossRandom rnd(all->get_real("SEED"));
    for (std::size_t n = 0; n < x.x.size(); ++n) {
      x.x[n] += a * rnd.next();
      x.y[n] += a * rnd.next();
      x.z[n] += a * rnd.next();
    }
    diags_.note(
        Diag::CoordinatesPerturbed, at(all->pos, 1), about(*all),
        "every node (" + std::to_string(x.x.size()) + ") moved by up to XALEA = " + number_text(a) +
            " along each axis, Radioss's random sequence from SEED = " + number_text(all->get_real("SEED")));
    return;
  }
  RadiossRandom rnd(groups.front()->get_real("SEED"));
  for (const auto* r : groups) {
    const auto it = grnod_ids_.find(r->id);
    if (it == grnod_ids_.end()) {
      diags_.error(Diag::MissingReference, at(r->pos, 1), about(*r),
                   "/RANDOM/GRNOD/" + std::to_string(r->id) + ": there is no /GRNOD/" +
                       std::to_string(r->id) +
                       " in the deck (the keyword line names the node group to perturb)");
      continue;
    }
    const auto* nodes = group_nodes(it->second);
    if (!nodes) continue;
    const double a = r->get_real("XALEA");
    for (const auto n : *nodes) {
      const auto k = static_cast<std::size_t>(n);
      x.x[k] += a * rnd.next();
      x.y[k] += a * rnd.next();
      x.z[k] += a * rnd.next();
    }
    diags_.note(Diag::CoordinatesPerturbed, at(r->pos, 1), about(*r),
                std::to_string(nodes->size()) + " node(s) of /GRNOD/" + std::to_string(r->id) +
                    " moved by up to XALEA = " + number_text(a) +
                    " along each axis, in Radioss's random sequence");
  }
}

}  // namespace radx::detail
