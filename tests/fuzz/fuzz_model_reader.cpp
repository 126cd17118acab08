// libFuzzer target: the engine's trust in the model file. The input is not an HDF5 file (that would fuzz the
// HDF5 library) but a list of changes to a valid model, as a damaged or hand-edited file would hold them:
// which model (of the seed model files), then records of (column, entry, kind of change, payload), a column
// being any dataset of the model file (tests/fuzz/model_columns.hpp). The changed model goes through the
// reader's checks (io::check_model_content); when they accept it, through what the engine does with a
// model: its IdMaps, the stable-step estimate and the engine's set-up and first cycles. A crash, a sanitizer
// report or a hang there is a change the checks let through and must not: a finding to fix in the checks.
//
// The seed model files are the starter's, named by RADX_FUZZ_MODELS (paths separated by ':'); scripts/fuzz.sh
// writes them from sample decks with the fuzz build's radx-starter.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "io/hdf5/model_file.hpp"
#include "io/hdf5/model_file_checks.hpp"
#include "model_columns.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/model/run_controls.hpp"
#include "solver/model/stable_step.hpp"

namespace {

using radx::model::Model;

// One change: 2 bytes column, 3 bytes entry, 1 byte kind, 8 bytes payload.
struct Change {
  std::uint32_t column = 0;
  std::uint32_t entry = 0;
  std::uint8_t kind = 0;
  std::uint64_t payload = 0;
};
constexpr std::size_t kChangeBytes = 14;
constexpr std::size_t kMaxChanges = 8;

enum Kind : std::uint8_t {
  Zero,
  MinusOne,
  Huge,          // 10,000,000 (the probe's), 1e300 for a real
  Extreme,       // INT_MIN / INT_MAX of the type by the payload's sign bit; +-inf for a real
  NotANumber,    // NaN for a real, the payload's bits for an integer
  CopyOther,     // the value of another entry of the column (payload: which)
  RandomBits,    // the payload's bits
  PlusOne,       // off by one (wrapping)
  MinusOneStep,  // off by one the other way
  Negate,
  Shorter,  // a variable-length array of the record one value shorter
  Longer,   // ... or longer
  kKinds
};

std::vector<Model>& seed_models() {
  static std::vector<Model> models = [] {
    std::vector<Model> out;
    const char* list = std::getenv("RADX_FUZZ_MODELS");
    if (list == nullptr || *list == '\0') {
      std::fprintf(stderr, "radx_fuzz_model: set RADX_FUZZ_MODELS to the seed model files (a:b:c)\n");
      std::abort();
    }
    std::stringstream ss(list);
    std::string path;
    while (std::getline(ss, path, ':')) {
      Model m;
      const auto r = radx::io::read_model_file(path, m);
      if (!r.ok()) {
        std::fprintf(stderr, "radx_fuzz_model: the seed %s is not a valid model file: %s\n", path.c_str(),
                     r.error.empty() ? r.problems.items.front().message.c_str() : r.error.c_str());
        std::abort();
      }
      out.push_back(std::move(m));
    }
    return out;
  }();
  return models;
}

template <class S>
void change_integer(S& x, S other, const Change& c) {
  using U = std::make_unsigned_t<S>;
  const bool negative = (c.payload >> 63) != 0;
  switch (c.kind) {
    case Zero: x = 0; break;
    case MinusOne: x = static_cast<S>(-1); break;
    case Huge: x = static_cast<S>(10'000'000); break;
    case Extreme: x = negative ? std::numeric_limits<S>::min() : std::numeric_limits<S>::max(); break;
    case CopyOther: x = other; break;
    case PlusOne: x = static_cast<S>(static_cast<U>(x) + 1u); break;
    case MinusOneStep: x = static_cast<S>(static_cast<U>(x) - 1u); break;
    case Negate: x = static_cast<S>(U{0} - static_cast<U>(x)); break;
    default: x = static_cast<S>(c.payload); break;
  }
}

void change_real(double& x, double other, const Change& c) {
  const bool negative = (c.payload >> 63) != 0;
  switch (c.kind) {
    case Zero: x = 0; break;
    case MinusOne: x = -1; break;
    case Huge: x = negative ? -1e300 : 1e300; break;
    case Extreme:
      x = negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
      break;
    case NotANumber: x = std::numeric_limits<double>::quiet_NaN(); break;
    case CopyOther: x = other; break;
    case PlusOne: x = std::nextafter(x, std::numeric_limits<double>::infinity()); break;
    case MinusOneStep: x = x * (1 + 1e-3); break;
    case Negate: x = -x; break;
    default: x = std::bit_cast<double>(c.payload); break;
  }
}

template <class S>
void change_scalar(S& x, S other, const Change& c) {
  if constexpr (std::is_same_v<S, double>) {
    change_real(x, other, c);
  } else if constexpr (std::is_same_v<S, bool>) {
    x = (c.payload & 1) != 0;
  } else if constexpr (std::is_enum_v<S>) {
    auto u = static_cast<std::underlying_type_t<S>>(x);
    change_integer(u, static_cast<std::underlying_type_t<S>>(other), c);
    x = static_cast<S>(u);
  } else {
    change_integer(x, other, c);
  }
}

// Applies `c` to the model; false when it names no entry (an empty column).
bool apply(Model& m, const Change& c, std::size_t columns) {
  const std::size_t target = c.column % columns;
  std::size_t k = 0;
  bool applied = false;
  radx::fuzz::for_each_column(m, [&](std::string_view, std::size_t size, auto&& at, auto&& resize) {
    if (k++ != target || size == 0) return;
    const std::size_t i = c.entry % size;
    applied = true;
    if (c.kind == Shorter || c.kind == Longer) {
      resize(i, c.kind == Longer);
      return;
    }
    auto& x = at(i);
    const auto other = at(static_cast<std::size_t>(c.payload % size));
    change_scalar(x, other, c);
  });
  return applied;
}

std::size_t column_count(Model& m) {
  std::size_t n = 0;
  radx::fuzz::for_each_column(m, [&](std::string_view, std::size_t, auto&&, auto&&) { ++n; });
  return n;
}

// What the engine does with a model before and during its first cycles.
void run_engine(Model& m) {
  std::int64_t ignored = 0;
  m.nodes.index.build(m.nodes.id, ignored);
  radx::io::schema::for_each_block(
      m, [&](const char*, radx::model::ElementBlock& b) { b.index.build(b.id, ignored); });
  (void)radx::model::estimate_stable_step(m, 10);
  radx::model::RunControls controls;
  controls.run_name = m.run_name;
  controls.t_stop = 1e30;
  radx::solver::EngineOptions options(1, 1);
  try {
    radx::solver::ExplicitEngine engine(m, controls, options);
    (void)engine.run([](const radx::solver::CycleReport& r) { return r.cycle < 3; });
  } catch (const std::exception&) {
    // The engine's own refusals (a condition it cannot hold) are reported, not crashes.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<Model>& seeds = seed_models();
  if (size < 1) return 0;
  Model m = seeds[data[0] % seeds.size()];
  const std::size_t columns = column_count(m);
  bool changed = false;
  for (std::size_t at = 1, n = 0; at + kChangeBytes <= size && n < kMaxChanges; at += kChangeBytes, ++n) {
    Change c;
    c.column = static_cast<std::uint32_t>(data[at]) | static_cast<std::uint32_t>(data[at + 1]) << 8;
    c.entry = static_cast<std::uint32_t>(data[at + 2]) | static_cast<std::uint32_t>(data[at + 3]) << 8 |
              static_cast<std::uint32_t>(data[at + 4]) << 16;
    c.kind = static_cast<std::uint8_t>(data[at + 5] % kKinds);
    std::memcpy(&c.payload, data + at + 6, sizeof c.payload);
    changed = apply(m, c, columns) || changed;
  }
  if (!changed) return 0;
  if (!radx::io::check_model_content(m).empty()) return 0;  // refused: the engine never sees it
  run_engine(m);
  return 0;
}
