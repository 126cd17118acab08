#include "apps/engine_outputs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/hdf5/results_writer.hpp"
#include "io/hdf5/time_history.hpp"
#include "io/listing/energy_plot.hpp"
#include "io/listing/unit_labels.hpp"
#include "parser/building/build_run_controls.hpp"
#include "solver/model/output_schedule.hpp"
#include "solver/outputs/result_fields.hpp"
#include "solver/outputs/time_history_values.hpp"

namespace radx::app {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
constexpr double kNoInterval = 1e29;  // /TFILE absent: dt_his = 1e30
// Energy samples kept for the chart: beyond this, every other one is dropped, so memory stays bounded
// however long the run (a chart cannot show more points than this anyway).
constexpr std::size_t kMaxEnergySamples = 16384;

// One extra array of the states: a cell or a node field and its buffer.
struct StateArray {
  bool cell = false;
  solver::CellField cell_field{};
  solver::NodeField node_field{};
  int shell_point = -1;  // >= 0: the stress at that through-thickness point of the shells
  std::vector<float> values;
};

std::string kind_path(model::ThKind k) {
  switch (k) {
    case model::ThKind::Node: return "node";
    case model::ThKind::Part: return "part";
    case model::ThKind::Inter: return "interface";
    case model::ThKind::Rwall: return "rwall";
    case model::ThKind::Shell: return "shell";
    case model::ThKind::Subset: return "subset";
    case model::ThKind::Brick: return "brick";
    case model::ThKind::Shell3: return "sh3n";
    case model::ThKind::Rbody: return "rbody";
    case model::ThKind::Section: return "section";
    case model::ThKind::Accel: return "accel";
    case model::ThKind::Spring: return "spring";
    case model::ThKind::Truss: return "truss";
    case model::ThKind::Beam: return "beam";
  }
  return "other";
}

std::string kind_name(model::ThKind k) {
  switch (k) {
    case model::ThKind::Node: return "node";
    case model::ThKind::Part: return "part";
    case model::ThKind::Inter: return "interface";
    case model::ThKind::Rwall: return "rigid wall";
    case model::ThKind::Shell: return "shell";
    case model::ThKind::Subset: return "subset";
    case model::ThKind::Brick: return "brick";
    case model::ThKind::Shell3: return "3-node shell";
    case model::ThKind::Rbody: return "rigid body";
    case model::ThKind::Section: return "section";
    case model::ThKind::Accel: return "accelerometer";
    case model::ThKind::Spring: return "spring";
    case model::ThKind::Truss: return "truss";
    case model::ThKind::Beam: return "beam";
  }
  return "";
}

std::int64_t user_id(const model::Model& m, model::ThKind k, std::int32_t i) {
  const auto n = static_cast<std::size_t>(i);
  switch (k) {
    case model::ThKind::Node: return m.nodes.id[n];
    case model::ThKind::Part: return m.parts[n].id;
    case model::ThKind::Inter: return m.interfaces[n].id;
    case model::ThKind::Rwall: return m.rigid_walls[n].id;
    case model::ThKind::Shell: return m.shells.id[n];
    case model::ThKind::Subset: return m.subsets[n].id;
    case model::ThKind::Brick:
      return n < m.bricks.size() ? m.bricks.id[n] : m.bricks20.id[n - m.bricks.size()];
    case model::ThKind::Shell3: return m.shells3.id[n];
    case model::ThKind::Rbody: return m.rigid_bodies[n].id;
    case model::ThKind::Section: return m.sections[n].id;
    case model::ThKind::Accel: return m.accelerometers[n].id;
    case model::ThKind::Spring: return m.springs.id[n];
    case model::ThKind::Truss: return m.trusses.id[n];
    case model::ThKind::Beam: return m.beams.id[n];
  }
  return 0;
}

}  // namespace

void remove_earlier_outputs(const std::string& out_dir, const std::string& root) {
  // The engine listing too: an earlier run's "NORMAL TERMINATION" beside a refused run would read as this
  // one's.
  for (const char* suffix :
       {"_0001.out", "_summary.json", "_summary.json.part", "_energy.csv", "_energy.csv.part", "_energy.png",
        "_energy.png.part.png", "_th.h5", "_th.h5.part"}) {
    const std::filesystem::path p = std::filesystem::path(out_dir) / (root + suffix);
    std::error_code ec;
    std::filesystem::remove(p, ec);
    if (ec) throw std::runtime_error("cannot remove " + p.string() + " of an earlier run: " + ec.message());
  }
}

struct EngineOutputs::Impl {
  const model::Model& model;
  const model::RunControls& controls;
  const solver::ExplicitEngine& engine;
  std::string out_dir, root;

  // Animation states.
  std::unique_ptr<io::ResultsWriter> results;
  std::vector<StateArray> arrays;
  std::vector<double> points;
  std::vector<float> displacement, velocity;
  std::vector<std::uint8_t> status;
  double next_state = kNever;
  double last_state_time = -kNever;

  // Time history.
  std::unique_ptr<io::TimeHistoryWriter> th;
  std::vector<solver::ThGroupSampler> samplers;
  std::vector<std::vector<double>> th_values;  // [1 + groups]
  double next_th = kNever;
  double last_th_time = -kNever;

  std::vector<io::EnergySample> energy;  // every energy_stride-th sample seen
  std::size_t energy_seen = 0, energy_stride = 1;
  io::EnergySample last_energy{};
  double seconds = 0;

  Impl(const model::Model& m, const model::RunControls& c, const solver::ExplicitEngine& e, std::string dir,
       std::string r)
      : model(m), controls(c), engine(e), out_dir(std::move(dir)), root(std::move(r)) {}

  [[nodiscard]] std::string unit(const solver::Dim& d) const {
    return io::unit_label(model.units, d.mass, d.length, d.time);
  }

  // Shells' von Mises and stress at the bottom, middle and top layers beside von_mises and stress, and the
  // stress at each through-thickness point beside stress (docs/results.md section 7), when the model has
  // shells: what Radioss writes for /ANIM/SHELL/TENS/STRESS/LOWER, UPPER and the layers.
  void add_shell_layer_arrays(std::vector<io::ResultArray>& specs) {
    if (model.shells.size() + model.shells3.size() == 0) return;
    const auto requested = [&](std::string_view name) {
      return std::any_of(specs.begin(), specs.end(),
                         [&](const io::ResultArray& s) { return s.name == name; });
    };
    const auto add = [&](solver::CellField f, int point, std::string name) {
      StateArray sa;
      sa.cell = true;
      sa.cell_field = f;
      sa.shell_point = point;
      io::ResultArray spec;
      spec.name = std::move(name);
      spec.components = solver::components(f);
      spec.on_points = false;
      spec.unit = unit(solver::field_dim(f));
      sa.values.resize(model.cell_count() * static_cast<std::size_t>(spec.components));
      specs.push_back(std::move(spec));
      arrays.push_back(std::move(sa));
    };
    using solver::CellField;
    if (requested("von_mises"))
      for (const CellField f : {CellField::VonMisesBottom, CellField::VonMisesMiddle, CellField::VonMisesTop})
        add(f, -1, std::string(solver::field_name(f)));
    if (requested("stress")) {
      for (const CellField f : {CellField::StressBottom, CellField::StressMiddle, CellField::StressTop})
        add(f, -1, std::string(solver::field_name(f)));
      for (int p = 0; p < solver::shell_points_max(engine); ++p)
        add(CellField::Stress, p, "stress_point_" + std::to_string(p + 1));
    }
  }

  void setup_states() {
    std::vector<io::ResultArray> specs;
    const std::pair<const std::vector<std::string>*, std::string_view> families[] = {
        {&controls.anim_vect, "/ANIM/VECT"},
        {&controls.anim_noda, "/ANIM/NODA"},
        {&controls.anim_elem, "/ANIM/ELEM"},
        {&controls.anim_tens, "/ANIM/TENS"}};
    for (const auto& [names, family] : families)
      for (const auto& name : *names) {
        const AnimFieldName* a = find_anim_field(family, name);
        if (a == nullptr)
          throw std::runtime_error(std::string(family) + "/" + name + " has no results array");
        const std::string array(a->array);
        if (array == "displacement" || array == "velocity") continue;  // always written
        bool seen = false;
        for (const auto& s : specs) seen = seen || s.name == array;
        if (seen) continue;
        StateArray sa;
        io::ResultArray spec;
        spec.name = array;
        if (const auto f = solver::cell_field_named(array)) {
          sa.cell = true;
          sa.cell_field = *f;
          spec.components = solver::components(*f);
          spec.on_points = false;
          spec.unit = unit(solver::field_dim(*f));
          sa.values.resize(model.cell_count() * static_cast<std::size_t>(spec.components));
        } else if (const auto g = solver::node_field_named(array)) {
          sa.node_field = *g;
          spec.components = solver::components(*g);
          spec.unit = unit(solver::field_dim(*g));
          sa.values.resize(model.nodes.size() * static_cast<std::size_t>(spec.components));
        } else {
          throw std::runtime_error(std::string(family) + "/" + name + ": the engine has no field " + array);
        }
        specs.push_back(spec);
        arrays.push_back(std::move(sa));
      }
    add_shell_layer_arrays(specs);
    results = std::make_unique<io::ResultsWriter>(model, out_dir, root, specs);
    points.resize(3 * model.nodes.size());
    displacement.resize(3 * model.nodes.size());
    velocity.resize(3 * model.nodes.size());
    status.resize(model.cell_count());
    next_state = 0.0;  // the first cycle
  }

  void setup_time_history() {
    const bool wanted = controls.th_dt < kNoInterval || !model.time_histories.empty();
    if (!wanted) return;
    std::vector<io::ThGroupLayout> layouts;
    io::ThGroupLayout global;
    global.path = "global";
    for (const auto& v : solver::global_th_variables()) {
      global.variables.push_back(v.name);
      global.units.push_back(v.name == "DMAS_PCT" ? "%" : unit(v.dim));
    }
    layouts.push_back(global);
    th_values.emplace_back(global.variables.size(), 0.0);
    for (const auto& g : model.time_histories) {
      io::ThGroupLayout l;
      l.path = kind_path(g.kind) + "/" + std::to_string(g.id);
      l.title = g.title;
      l.object_kind = kind_name(g.kind);
      for (const auto o : g.objects) l.objects.push_back(user_id(model, g.kind, o));
      if (std::any_of(g.skews.begin(), g.skews.end(), [](std::int64_t s) { return s != 0; }))
        l.skews = g.skews;
      samplers.emplace_back(engine, g);
      // The deck's variables, then the instantaneous values of the interval means (FNX_INST, ...).
      l.variables = samplers.back().variables();
      for (const auto& v : l.variables) l.units.push_back(unit(solver::th_variable_dim(g.kind, v)));
      th_values.emplace_back(samplers.back().size(), 0.0);
      layouts.push_back(std::move(l));
    }
    const std::string path = (std::filesystem::path(out_dir) / (root + "_th.h5")).string();
    std::error_code ec;
    std::filesystem::remove(path + ".part", ec);  // a stray file of a killed run
    th = std::make_unique<io::TimeHistoryWriter>(path, std::move(layouts), model.units.time_name);
    next_th = 0.0;
  }

  void write_state(double time, double dt1) {
    const auto t0 = std::chrono::steady_clock::now();
    solver::gather_points(engine, points);
    solver::gather_node_field(engine, solver::NodeField::Displacement, dt1, displacement);
    solver::gather_node_field(engine, solver::NodeField::Velocity, dt1, velocity);
    solver::gather_element_status(engine, status);
    io::ResultState st;
    st.time = time;
    st.points = points;
    st.displacement = displacement;
    st.velocity = velocity;
    st.element_status = status;
    for (auto& a : arrays) {
      if (a.shell_point >= 0)
        solver::gather_shell_point_stress(engine, a.shell_point, a.values);
      else if (a.cell)
        solver::gather_cell_field(engine, a.cell_field, a.values);
      else
        solver::gather_node_field(engine, a.node_field, dt1, a.values);
      st.arrays.emplace_back(a.values);
    }
    if (results->write_state(st)) last_state_time = time;
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  void write_th_row(const solver::CycleReport& r, bool force_flush) {
    const auto t0 = std::chrono::steady_clock::now();
    solver::global_th_values(engine, r, th_values[0]);
    for (std::size_t g = 0; g < samplers.size(); ++g) samplers[g].sample(engine, r, th_values[g + 1]);
    std::vector<std::span<const double>> spans(th_values.begin(), th_values.end());
    // The writer flushes by itself every few thousand rows or every second of wall time.
    th->append(r.time, spans);
    last_th_time = r.time;
    if (force_flush) th->flush();
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
};

EngineOutputs::EngineOutputs(const model::Model& m, const model::RunControls& c,
                             const solver::ExplicitEngine& engine, const std::string& out_dir,
                             const std::string& root)
    : impl_(std::make_unique<Impl>(m, c, engine, out_dir, root)) {
  impl_->setup_states();
  impl_->setup_time_history();
}

EngineOutputs::~EngineOutputs() = default;

void EngineOutputs::accumulate(const solver::CycleReport& r) {
  for (auto& sampler : impl_->samplers)
    if (sampler.averages()) sampler.accumulate(impl_->engine, r);
}

bool EngineOutputs::due(double time) const {
  return time >= impl_->next_state || time >= impl_->next_th;
}

bool EngineOutputs::state_due(double time) const {
  return time >= impl_->next_state;
}

void EngineOutputs::on_report(const solver::CycleReport& r) {
  auto& s = *impl_;
  const auto& c = s.controls;
  const auto& e = r.energy;
  s.last_energy =
      io::EnergySample{r.time,
                       e.kinetic_t + e.kinetic_r,
                       e.internal,
                       e.hourglass,
                       e.contact_elastic + e.contact_damping + e.contact_friction + e.contact_lagrange,
                       e.external_work,
                       e.total()};
  if (s.energy_seen++ % s.energy_stride == 0) {
    if (s.energy.size() == kMaxEnergySamples) {
      // Samples kept are seen numbers 0, stride, 2 stride...: keeping the even ones keeps multiples of
      // twice the stride.
      std::size_t kept = 0;
      for (std::size_t i = 0; i < s.energy.size(); i += 2) s.energy[kept++] = s.energy[i];
      s.energy.resize(kept);
      s.energy_stride *= 2;
    }
    if ((s.energy_seen - 1) % s.energy_stride == 0) s.energy.push_back(s.last_energy);
  }
  if (r.time >= s.next_state) {
    s.write_state(r.time, r.dt1);
    // Next /ANIM/DT time strictly after this one (several intervals may pass in one cycle).
    double next = kNever;
    if (c.anim_dt > 0) {
      next = model::next_output_time(c.anim_start, c.anim_dt, r.time);
      if (next > c.anim_stop) next = kNever;
    }
    s.next_state = next;
  }
  if (s.th && r.time >= s.next_th) {
    s.write_th_row(r, s.th->rows() == 0);  // the file exists from the first row on
    double next = kNever;
    if (c.th_dt == 0.0) {
      next = std::nextafter(r.time, kNever);  // /TFILE dt_his 0: every cycle
    } else if (c.th_dt < kNoInterval) {
      next = model::next_output_time(0.0, c.th_dt, r.time);
    }
    s.next_th = next;
  }
}

void EngineOutputs::finish(const solver::RunResult& result, bool plot, std::ostream& warn) {
  auto& s = *impl_;
  // What follows happens after the engine's wall clock stopped: it is not part of seconds_writing().
  const double in_run = s.seconds;
  if (result.time > s.last_state_time) s.write_state(result.time, result.dt1);
  if (s.th) {
    // The last full report is the run's last cycle unless an error stopped it first; a row then would mix
    // that report's energies with the nodes of the later state, so none is written.
    if (result.last.time > s.last_th_time && result.last.time == result.time)
      s.write_th_row(result.last, false);
    const auto t0 = std::chrono::steady_clock::now();
    s.th->flush();
    s.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  s.seconds = in_run;
  if (s.energy_seen > 0 && (s.energy.empty() || s.energy.back().time != s.last_energy.time))
    s.energy.push_back(s.last_energy);  // the run's last sample, even when thinning skipped it
  if (s.energy.empty()) return;
  io::EnergyPlotRequest req;
  req.csv_path = (std::filesystem::path(s.out_dir) / (s.root + "_energy.csv")).string();
  req.png_path = (std::filesystem::path(s.out_dir) / (s.root + "_energy.png")).string();
  req.title = s.root + ": energy balance";
  req.time_unit = s.model.units.time_name;
  req.energy_unit = io::unit_label(s.model.units, 1, 2, -2);
  req.samples = std::move(s.energy);  // the last use: a copy would double the samples at the very end
  // The CSV is the data and is always written: a failure to write it is one of the run's outputs lost. The
  // chart is a convenience (--no-plot skips it and its Python start-up): a missing tool is a warning.
  std::string error;
  if (!io::write_energy_csv(req, error)) throw std::runtime_error("energy balance not written: " + error);
  std::string warning;
  if (plot && !io::draw_energy_png(req, io::kDebianPython, warning))
    warn << "radx-engine: warning: " << warning << '\n';
}

int EngineOutputs::states_written() const {
  return impl_->results->states_written();
}
double EngineOutputs::seconds_writing() const {
  return impl_->seconds;
}
std::string EngineOutputs::series_path() const {
  return impl_->results->series_path();
}

}  // namespace radx::app
