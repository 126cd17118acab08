#include "apps/starter_pipeline.hpp"

#include "apps/engine_pipeline.hpp"

#include "apps/build_info.hpp"

#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "contact/type7_prepare.hpp"
#include "io/hdf5/model_file.hpp"
#include "io/listing/starter_listing.hpp"
#include "io/text_file.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/building/plausibility.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/deck_echo.hpp"
#include "solver/model/masses.hpp"
#include "solver/model/run_files.hpp"
#include "solver/model/stable_step.hpp"

namespace radx::app {

namespace fs = std::filesystem;

namespace {

std::string engine_deck_beside(const std::string& deck) {
  const fs::path p(deck);
  std::string stem = p.stem().string();
  if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, "_0000") == 0) {
    const fs::path e = p.parent_path() / (stem.substr(0, stem.size() - 5) + "_0001" + p.extension().string());
    if (fs::exists(e)) return e.string();
  }
  return {};
}

// An exponential /CTCLAW law given by pe gets lambda = (K / A_s) / pe per pair: its KcMax must not be below
// the largest initial stiffness lambda pz, which the starter knows only now, with K and A_s.
void check_pe_laws(const Deck& deck, const model::Model& model, Diagnostics& diags) {
  for (const auto& in : model.interfaces) {
    const auto& law = in.law;
    if (!(law.kc_max > 0)) continue;
    const auto s = contact::pe_law_initial_stiffness_max(in);
    if (!(law.kc_max < s.stiffness)) continue;
    const KeywordRecord* r = nullptr;
    for (const auto& rec : deck.records)
      if (rec.decl->path == "/CTCLAW" && rec.id == in.contact_law_id) r = &rec;
    Where where{};
    if (r != nullptr) {
      where = deck.where(r->pos, 1);
      std::string lower;
      for (char c : r->text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      const auto at = lower.find("kcmax");
      if (at != std::string::npos && at < r->text_pos.size())
        where = deck.where(r->text_pos[at], static_cast<int>(r->text_column[at]));
    }
    std::ostringstream msg;
    msg << "/CTCLAW/" << in.contact_law_id << " KcMax: KcMax = " << law.kc_max
        << " is below the largest initial stiffness of the law on interface " << in.id
        << ", lambda pz = pz (K / A_s) / pe = " << law.pz << " * (" << s.k << " / " << s.area << ") / "
        << law.pe << " = " << s.stiffness
        << " (K the largest pair stiffness, A_s the smallest tributary area of its secondary nodes); need "
           "KcMax >= "
        << s.stiffness << ", or a larger pe";
    diags.error(Diag::BadContactLaw, where,
                About{"/CTCLAW", in.contact_law_id, r ? std::string_view(r->title) : ""}, msg.str());
  }
}

// The first /INTER/TYPE7 or /INTER/LAGDT/TYPE7 record of the deck with id `id`, or null.
const KeywordRecord* type7_record(const Deck& deck, std::int64_t id) {
  for (const auto& rec : deck.records)
    if (rec.id == id && (rec.decl->path == "/INTER/TYPE7" || rec.decl->path == "/INTER/LAGDT/TYPE7"))
      return &rec;
  return nullptr;
}

// A warning per interface with secondary nodes inside the gap at the start, saying what its Inacti does with
// them. True when the starter moved some (Inacti 3): the masses are then computed again.
bool warn_initial_penetrations(const Deck& deck, const model::Model& model, const std::string& deck_path,
                               Diagnostics& diags) {
  bool moved = false;
  for (const auto& in : model.interfaces) {
    if (in.initial_penetrations == 0) continue;
    moved = moved || in.inacti == 3;
    std::ostringstream msg;
    msg << in.initial_penetrations << " secondary node(s) start inside the gap; largest penetration "
        << in.max_initial_penetration << " at node " << in.max_penetration_node << "; Inacti = " << in.inacti
        << (in.inacti == 0   ? ": no action, the penalty will push them out (this may inject energy)"
            : in.inacti == 1 ? ": their stiffness is deactivated"
            : in.inacti == 2 ? ": the stiffness of the main segments concerned is deactivated"
            : in.inacti == 3 ? ": the starter moved them out to the gap surface"
                             : ": their gap starts reduced and grows back as the pair opens");
    const auto* r = type7_record(deck, in.id);
    diags.warning(Diag::InitialPenetration, r ? deck.where(r->pos, 1) : Where{deck_path},
                  About{in.lagdt ? "/INTER/LAGDT/TYPE7" : "/INTER/TYPE7", in.id, in.title}, msg.str());
  }
  return moved;
}

// The model of a readable deck, its interfaces prepared (gaps, stiffnesses, initial penetrations) and the
// checks that need them, when it built without errors.
model::Model build_prepared_model(const Deck& deck, const std::string& deck_path, Diagnostics& diags) {
  model::Model model = build_model(deck, diags);
  if (diags.has_errors()) return model;
  contact::prepare_type7_interfaces(model);
  if (warn_initial_penetrations(deck, model, deck_path, diags)) model::compute_lumped_masses(model);
  check_pe_laws(deck, model, diags);
  return model;
}

// The end time lives in the engine deck: read it when it is there, also when only the starter runs, so that
// an absurd one is caught before the run starts; its own problems are reported only on request.
void check_engine_deck_beside(const StarterOptions& opt, bool readable, const model::Model& model,
                              const model::StepEstimate& step, Diagnostics& diags) {
  const std::string engine = model::is_one_file_deck(opt.deck) ? opt.deck : engine_deck_beside(opt.deck);
  if (engine.empty()) return;
  Diagnostics unreported;
  Diagnostics& engine_diags = opt.check_engine_deck ? diags : unreported;
  EngineDeck engine_deck;
  model::RunControls controls = read_run_controls(engine, engine_diags, &engine_deck);
  if (readable && opt.check_engine_deck) {
    std::vector<std::int64_t> body_ids;
    for (const auto& b : model.rigid_bodies) body_ids.push_back(b.id);
    check_rigid_body_switches(engine_deck, body_ids, controls, diags);
  }
  check_cycle_count(engine_deck, controls, model, step, diags);
}

// The total mass and each interface's gap and stiffness ranges, as the prepared model has them.
void print_prepared_figures(std::ostream& out, const model::Model& model) {
  out << "  total mass " << std::setprecision(6) << model.total_mass << ' ' << model.units.mass_name << '\n';
  for (const auto& in : model.interfaces) {
    out << "  interface " << in.id << (in.lagdt ? " (LAGDT)" : "") << ": " << in.secondary_nodes.size()
        << " secondary nodes, gap " << in.gap_lo << " to " << in.gap_hi << ", stiffness " << in.stiff_lo
        << " to " << in.stiff_hi << '\n';
  }
}

// The summary on standard output: the model's counts, its mass and interfaces, the diagnostics' counts.
void print_starter_summary(std::ostream& out, const StarterOptions& opt, bool readable,
                           const model::Model& model, const StarterResult& res) {
  out << "radx starter: " << opt.deck << '\n';
  if (readable) {
    out << "  nodes " << model.nodes.size() << ", shells " << model.shells.size() << ", 3-node shells "
        << model.shells3.size() << ", bricks " << model.bricks.size()
        << (model.tetras.size() == 0 ? std::string() : ", tetrahedra " + std::to_string(model.tetras.size()))
        << ", parts " << model.parts.size() << ", interfaces " << model.interfaces.size() << '\n';
    if (res.errors > 0) {
      // Masses, gaps and stiffnesses of a model that is not whole would mislead: say they are missing.
      out << "  mass, gaps and stiffnesses not computed: the starter stopped on the errors above\n";
    } else {
      print_prepared_figures(out, model);
    }
  }
  out << "  " << res.errors << " error(s), " << res.warnings << " warning(s)\n";
}

// The model file (a deck without errors; an earlier one that no longer matches the deck is removed) and the
// listing NAME_0000.out.
void write_starter_outputs(const StarterOptions& opt, const Deck& deck, const model::Model& model,
                           const model::StepEstimate& step, const Diagnostics& diags,
                           std::chrono::steady_clock::time_point t0, StarterResult& res, std::ostream& out,
                           std::ostream& err) {
  std::error_code ec;
  fs::create_directories(opt.out_dir, ec);
  const std::string root = (fs::path(opt.out_dir) / model::starter_output_root(opt.deck)).string();
  res.listing_path = root + ".out";
  const std::string model_path = root + ".hdf";
  std::string error;
  if (!diags.has_errors()) {
    const io::ModelFileOrigin origin =
        io::model_file_origin(model::run_output_root(opt.deck), deck.files, std::string(build_commit()));
    if (!io::write_model_file(model, model_path, origin, error)) {
      err << opt.deck << ": error: cannot write the model file: " << error << '\n';
      ++res.errors;
    } else {
      res.model_path = model_path;
    }
  } else if (fs::exists(model_path)) {
    // A model file from an earlier run no longer matches this deck: do not leave it for the engine.
    fs::remove(model_path, ec);
    out << "  removed the stale model file " << model_path << " (it does not match the deck any more)\n";
  }
  io::StarterListingInput li;
  li.deck_path = opt.deck;
  li.program_version = RADX_VERSION " (" RADX_ARCH ")";
  li.model = &model;
  for (const auto& in : model.interfaces) {
    std::vector<std::string> echo;
    for (const auto& rec : deck.records)
      if (rec.id == in.id && (rec.decl->path == "/INTER/TYPE7" || rec.decl->path == "/INTER/LAGDT/TYPE7"))
        echo = echo_keyword(rec);
    li.interface_echo.push_back(std::move(echo));
  }
  li.diagnostics = diags.lines();
  li.errors = res.errors;
  li.warnings = res.warnings;
  li.model_file = res.model_path;
  li.smallest_steps = step.smallest;
  li.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ostringstream listing;
  io::write_starter_listing(listing, li);
  if (!io::write_text_atomically(res.listing_path, listing.str(), error)) {
    err << opt.deck << ": error: " << error << '\n';
    ++res.errors;
  }
  out << "  listing " << res.listing_path << '\n';
  if (!res.model_path.empty()) out << "  model file " << res.model_path << '\n';
}

}  // namespace

StarterResult run_starter(const StarterOptions& opt, std::ostream& out, std::ostream& err) {
  const auto t0 = std::chrono::steady_clock::now();
  StarterResult res;
  // A new model makes the engine results of this name another model's: removed first, also when the deck
  // is refused, so none is left beside the new listing. Under the run's lock: not under a running engine.
  RunLock lock;
  if (opt.write_outputs) {
    try {
      std::error_code ec;
      fs::create_directories(opt.out_dir, ec);
      lock = RunLock(opt.out_dir, model::run_output_root(opt.deck));
      remove_earlier_engine_outputs(opt.out_dir, model::run_output_root(opt.deck));
    } catch (const std::exception& e) {
      err << "radx-starter: error: " << e.what() << '\n';
      res.errors = 1;
      res.exit_code = 1;
      return res;
    }
  }
  Diagnostics diags;
  ReadOptions read_opt;
  read_opt.allow_substitutions = opt.allow_substitutions;
  const Deck deck = read_starter_deck(opt.deck, diags, read_opt);
  const bool readable = !deck.records.empty();
  model::Model model;
  if (readable) model = build_prepared_model(deck, opt.deck, diags);
  model::StepEstimate step;
  if (readable && !diags.has_errors()) {
    step = model::estimate_stable_step(model, 10);
    check_initial_step(deck, model, step, diags);
    check_contact_step(deck, model, step, diags);
  }
  check_engine_deck_beside(opt, readable, model, step, diags);
  diags.sort();
  res.errors = diags.error_count();
  res.warnings = diags.warning_count();
  diags.print(err);
  print_starter_summary(out, opt, readable, model, res);
  if (opt.write_outputs && readable) write_starter_outputs(opt, deck, model, step, diags, t0, res, out, err);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out << "  starter time " << std::fixed << std::setprecision(3) << secs << " s\n";
  res.exit_code = res.errors > 0 ? 1 : 0;
  return res;
}

}  // namespace radx::app
