// Engine deck -> RunControls. Rules (docs/theory/deck-format.md section 3, docs/theory/type7-lagdt.md
// section 6):
// * /RUN/name[/irun]: Tstop > 0 required; irun 1 to 99999, from the file name (NAME_0003.rad: 3; else 1) when
//   absent or 0 (a note), as the Radioss engine takes it; a restart letter is refused (radx writes no
//   restarts).
// * /PRINT/n/nh: default -100; n != 0, |n| the line interval, n < 0 also to standard output; nh >= 0.
// * /TFILE: dt_his >= 0, 0 meaning every cycle (Radioss then keeps the starter's interval, 0: a row every
//   cycle); without /TFILE, 1e30 (no time history beyond the first and last states).
// * /ANIM/DT Tstart dT [Tstop Nframes fct_ID]: Tstop 0 -> 1e20, negative Tstop or Tstart an error; dT <= 0 is
//   an error unless Nframes > 0 gives it as (end - Tstart) / Nframes; a function id is not implemented.
// * /DT: Tscale 0 -> 0.9, Tmin 0 -> 0; action Stop (the run stops when the element step reaches Tmin).
//   The per-family controls (/DT/BRICK|SHELL|SH_3N/CST, action Constant: small-strain switch) default to
//   the /DT values: a family Tscale or Tmin of 0 takes the /DT value, and a family not given is a copy of
//   /DT (action Stop, given = false), so the engine can read the three families directly.
// * /DT/NODA/CST: action AddMass; Tscale 0 -> 0.9; third value: added-mass percentage that stops the run.
// * /DT/INTER/CST -> AddMass, /DEL -> Delete, /LAG -> Lagrange; Tscale 0 -> 0.9. /DEL has precedence
//   over the others (a warning says the others are ignored); /CST with /LAG is an error.
// * /STOP Emax Mmax Nmax [NTH NANIM [NERR_POSIT]]: 0 -> 1e30; negatives are errors; flags 0 or 1.
// * /ANIM/ELEM|VECT|TENS|NODA/name: a name of anim_field_names() is stored in its canonical spelling, each
//   once, in deck order; any other name, or further fields after the name, is an output radx does not
//   write: a warning (RX311), and the run goes on.
// * /RBODY/ON|OFF ids: 0 switches nothing (a note), a negative id names no body (a warning), as Radioss
//   passes over both; an id both switched on and off is an error. check_rigid_body_switches then drops, with
//   a warning, the ids the model lacks.
// * Every singleton keyword given twice is an error at the second one.
#include "parser/building/build_run_controls.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "parser/reading/closest_names.hpp"
#include "parser/reading/field_parse.hpp"
#include "solver/model/output_schedule.hpp"
#include "solver/model/run_files.hpp"

namespace radx {

namespace {

constexpr double kOff = 1e30;          // /STOP values and /TFILE: never
constexpr double kAnimNever = 1e20;    // /ANIM/DT Tstop 0
constexpr double kDefaultScale = 0.9;  // Tscale 0

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

class Builder {
 public:
  Builder(const EngineDeck& deck, Diagnostics& diags) : deck_(deck), diags_(diags) {}

  // A record with a value that is not a number was reported by the reader (RX202), and its unreadable value
  // reads as 0: a range error about that 0 would be a second, wrong report of the same fault.
  void error(const EngineRecord& r, Diag code, std::string msg) {
    if (r.has_unreadable) return;
    diags_.error(code, deck_.where(r.pos, 1), About{r.decl->path}, std::move(msg));
  }
  void warning(const EngineRecord& r, Diag code, std::string msg) {
    diags_.warning(code, deck_.where(r.pos, 1), About{r.decl->path}, std::move(msg));
  }

  // The records of the keyword radx reads at `path`. A keyword it does not read may share the path (the
  // refused /DT/... beside /DT): the reader reported it, and it is not built.
  std::vector<const EngineRecord*> read_of(std::string_view path) const {
    auto recs = deck_.of(path);
    std::erase_if(recs, [](const EngineRecord* r) { return r->decl->support != schema::Support::Read; });
    return recs;
  }

  // The one record of a singleton keyword; a second one is an error that points at the first.
  const EngineRecord* single(std::string_view path) {
    const auto recs = read_of(path);
    if (recs.empty()) return nullptr;
    for (std::size_t k = 1; k < recs.size(); ++k) {
      const Where first = deck_.where(recs[0]->pos);
      error(*recs[k], Diag::DuplicateSingleton,
            std::string(path) + " is given again (first at " + std::string(first.file) + ":" +
                std::to_string(first.line) + "); give it once");
    }
    return recs[0];
  }

  // Header field k as an integer into `out` (`dflt` when absent). False, after an error, when the field is
  // not an integer.
  bool header_int(const EngineRecord& r, std::size_t k, std::int64_t dflt, std::int64_t& out) {
    out = dflt;
    if (k >= r.header.size()) return true;
    const std::string_view field =
        k < r.decl->header_fields.size() ? r.decl->header_fields[k] : std::string_view("field");
    if (parse_int(r.header[k], out) != NumberStatus::Ok) {
      error(r, Diag::BadInteger,
            std::string(field) + " = '" + r.header[k] + "' in the keyword line is not an integer");
      out = dflt;
      return false;
    }
    return true;
  }

  // Tscale and Tmin of a /DT line into `c`. Tscale 0 -> default_scale, Tmin 0 -> default_tmin.
  void read_dt(const EngineRecord& r, model::DtControl& c, double default_scale, double default_tmin,
               model::DtAction action) {
    const double s = r.value(0, 0);
    const double tmin = r.value(0, 1);
    c.given = true;
    c.action = action;
    c.scale = default_scale;
    c.t_min = default_tmin;
    if (s < 0) {
      error(r, Diag::ValueOutOfRange,
            "Tscale = " + num(s) + " is negative; give 0 < Tscale <= 1 (0 means " + num(default_scale) + ")");
    } else if (s > 0) {
      c.scale = s;
      if (s > 1)
        warning(r, Diag::ValueOutOfRange,
                "Tscale = " + num(s) + " is above 1: the time step exceeds the stability limit estimate");
    }
    if (tmin < 0) {
      error(r, Diag::ValueOutOfRange, "Tmin = " + num(tmin) + " is negative; give Tmin >= 0 (0: no minimum)");
    } else if (tmin > 0) {
      c.t_min = tmin;
    }
  }

  model::RunControls build();

 private:
  void run(model::RunControls& rc);
  void print(model::RunControls& rc);
  void tfile(model::RunControls& rc);
  void anim_dt(model::RunControls& rc);
  void check_anim_count(const EngineRecord& r, model::RunControls& rc);
  void anim_names(model::RunControls& rc);
  void time_steps(model::RunControls& rc);
  void step_bounds(model::RunControls& rc);
  void element_time_steps(model::RunControls& rc);
  void nodal_time_step(model::RunControls& rc);
  void interface_time_step(model::RunControls& rc);
  void stop(model::RunControls& rc);
  void rbodies(model::RunControls& rc);
  void versions();

  const EngineDeck& deck_;
  Diagnostics& diags_;
};

void Builder::run(model::RunControls& rc) {
  const EngineRecord* r = single("/RUN");
  if (!r) return;  // the reader reports a missing /RUN (RX801)
  if (!r->header.empty()) {
    // The reader stores keyword fields in upper case; keep the name as written when it can be found.
    rc.run_name = r->header[0];
    std::vector<std::string> parts(1);
    for (char c : r->written) {
      if (c == '/')
        parts.emplace_back();
      else if (c != ' ' && c != '\t')
        parts.back() += c;
    }
    if (parts.size() >= 3 && upper(parts[2]) == r->header[0]) rc.run_name = parts[2];
  }
  std::int64_t irun = 1;
  if (header_int(*r, 1, 1, irun)) {
    // irun 0 leaves the number to the file name, as the Radioss engine does (read_run_controls).
    if (irun < 0 || irun > 99999) {
      error(*r, Diag::ValueOutOfRange,
            "run number irun = " + std::to_string(irun) +
                " is out of range; engine runs are numbered 1 to 99999, 0 taking the file name's number");
    } else if (irun > 0) {
      rc.run_number = static_cast<int>(irun);
    }
  }
  if (r->header.size() > 2) {
    error(*r, Diag::UnimplementedOption,
          "restart letter '" + r->header[2] +
              "': radx writes no restart files and cannot restart a run; remove the letter "
              "(/RUN/name/irun)");
  }
  if (!r->lines.empty() && !r->lines[0].empty()) {
    const double t = r->lines[0][0];
    if (t <= 0)
      error(*r, Diag::ValueOutOfRange, "Tstop = " + num(t) + ": the end time of the run must be > 0");
    else
      rc.t_stop = t;
  }
}

void Builder::print(model::RunControls& rc) {
  const EngineRecord* r = single("/PRINT");
  if (!r) return;
  std::int64_t n = -100, nh = 0;
  if (header_int(*r, 0, -100, n)) {
    if (n == 0 || n < -1000000000 || n > 1000000000) {
      error(*r, Diag::ValueOutOfRange,
            "/PRINT/n with n = " + std::to_string(n) +
                ": give the listing line interval in cycles, non-zero (negative: also to standard "
                "output; default -100)");
    } else {
      rc.print_every = static_cast<int>(n < 0 ? -n : n);
      rc.print_stdout = n < 0;
    }
  }
  if (header_int(*r, 1, 0, nh)) {
    if (nh < 0 || nh > 1000000000)
      error(*r, Diag::ValueOutOfRange,
            "/PRINT/n/nh with nh = " + std::to_string(nh) +
                ": the header interval in lines must be >= 0 (0: header once)");
    else
      rc.print_header_every = static_cast<int>(nh);
  }
}

void Builder::tfile(model::RunControls& rc) {
  const EngineRecord* r = single("/TFILE");
  if (!r) return;
  std::int64_t ityp = 0;
  if (header_int(*r, 0, 0, ityp) && (ityp < 0 || ityp > 4))
    error(
        *r, Diag::ValueOutOfRange,
        "/TFILE/ityp = " + std::to_string(ityp) + ": the format must be 0 to 4 (radx writes its own format)");
  if (!r->lines.empty() && !r->lines[0].empty()) {
    const double dt = r->lines[0][0];
    if (dt < 0)
      error(*r, Diag::ValueOutOfRange,
            "dt_his = " + num(dt) +
                ": the time-history interval must be >= 0 (0: every cycle; remove /TFILE for none)");
    else
      rc.th_dt = dt;
    if (dt > 0 && rc.t_stop > 0 && dt < model::time_resolution(rc.t_stop)) {
      warning(*r, Diag::ValueOutOfRange,
              "dt_his = " + num(dt) + " is below the time resolution at the end time " + num(rc.t_stop) +
                  " (" + num(model::time_resolution(rc.t_stop)) + "): the deck asks for " +
                  num(rc.t_stop / dt) +
                  " rows, and an interval this small cannot advance the time; radx writes a row every cycle, "
                  "as dt_his = 0 asks");
      rc.th_dt = 0.0;
    }
  }
}

void Builder::anim_dt(model::RunControls& rc) {
  const EngineRecord* r = single("/ANIM/DT");
  if (!r || r->lines.empty() || r->lines[0].size() < 2) return;  // the reader reports missing values
  const auto& v = r->lines[0];
  const double start = v[0], dt = v[1];
  const double stop = v.size() > 2 ? v[2] : 0.0;
  const double nframes = v.size() > 3 ? v[3] : 0.0;
  const double fct = v.size() > 4 ? v[4] : 0.0;
  bool ok = true;
  if (start < 0) {
    error(*r, Diag::ValueOutOfRange, "Tstart = " + num(start) + " is negative; give Tstart >= 0");
    ok = false;
  }
  if (stop < 0) {
    error(*r, Diag::ValueOutOfRange,
          "Tstop = " + num(stop) + " is negative; give Tstop >= 0 (0: until the end of the run)");
    ok = false;
  }
  const double end = stop > 0 ? stop : kAnimNever;
  if (stop > 0 && stop < start) {
    error(*r, Diag::InconsistentValues,
          "Tstop = " + num(stop) + " is before Tstart = " + num(start) +
              ": no animation state would be written");
    ok = false;
  }
  if (fct != 0) {
    error(*r, Diag::UnimplementedOption,
          "fct_ID = " + num(fct) + ": animation times from a function are not implemented in radx; give dT");
    ok = false;
  }
  if (nframes < 0 || nframes > 1e9 || nframes != std::floor(nframes)) {
    error(*r, Diag::ValueOutOfRange, "Nframes = " + num(nframes) + ": give a whole number of frames >= 0");
    ok = false;
  }
  double interval = dt;
  if (dt <= 0) {
    if (nframes > 0) {
      const double last = std::min(end, rc.t_stop > 0 ? rc.t_stop : end);
      interval = (last - start) / nframes;
      if (!(interval > 0)) {
        error(*r, Diag::InconsistentValues,
              "dT = " + num(dt) + " with Nframes = " + num(nframes) +
                  ": the frames span no time (end before Tstart); give dT > 0");
        ok = false;
      }
    } else {
      error(*r, Diag::ValueOutOfRange,
            "dT = " + num(dt) + ": the animation interval must be > 0 (or give Nframes > 0)");
      ok = false;
    }
  } else if (nframes > 0) {
    warning(*r, Diag::InconsistentValues,
            "Nframes = " + num(nframes) + " is ignored: dT = " + num(dt) + " is given and sets the interval");
  }
  if (!ok) return;
  rc.anim_start = start;
  rc.anim_dt = interval;
  rc.anim_stop = end;
  check_anim_count(*r, rc);
  if (rc.t_stop > 0 && start > rc.t_stop)
    warning(*r, Diag::InconsistentValues,
            "Tstart = " + num(start) + " is after the end of the run (" + num(rc.t_stop) +
                "): only the first and last states are written");
}

// An interval below the time resolution at the last state time cannot advance the time there: it is raised
// to that resolution (solver/model/output_schedule.hpp would fall back to the next double anyway), which
// makes the schedule a state every cycle, and said with the count the deck asks for. How many states the run
// would write is known only with the model's step: check_output_count says it when it is many.
void Builder::check_anim_count(const EngineRecord& r, model::RunControls& rc) {
  const double last = std::min(rc.anim_stop, rc.t_stop);
  if (!(rc.t_stop > 0) || !(last > rc.anim_start)) return;
  const double resolution = model::time_resolution(last);
  if (rc.anim_dt >= resolution) return;
  warning(r, Diag::ValueOutOfRange,
          "dT = " + num(rc.anim_dt) + " is below the time resolution at the last state time " + num(last) +
              " (" + num(resolution) + "): the deck asks for " + num((last - rc.anim_start) / rc.anim_dt) +
              " states, and no schedule can step by less; dT is raised to " + num(resolution) +
              ", a state every cycle (check the unit)");
  rc.anim_dt = resolution;
}

void Builder::anim_names(model::RunControls& rc) {
  struct Family {
    std::string_view path;
    std::vector<std::string>* out;
    const char* what;
  };
  const Family families[] = {{"/ANIM/ELEM", &rc.anim_elem, "an element scalar field"},
                             {"/ANIM/VECT", &rc.anim_vect, "a nodal vector field"},
                             {"/ANIM/TENS", &rc.anim_tens, "an element tensor field"},
                             {"/ANIM/NODA", &rc.anim_noda, "a nodal scalar field"}};
  for (const auto& f : families) {
    for (const EngineRecord* r : read_of(f.path)) {
      if (r->header.empty()) continue;  // the reader reports the missing name (RX306)
      // An output radx does not write changes no result: a warning, and the run goes on without it.
      const AnimFieldName* a = find_anim_field(f.path, r->header[0]);
      if (!a && !radioss_knows_anim_field(f.path, r->header[0])) {
        // Radioss would not write it either: a slip of the hand, which a warning would let run for hours
        // without the field the user asked for.
        const std::string suggestion = did_you_mean(r->header[0], anim_names_of_family(f.path));
        error(*r, Diag::UnknownKeyword,
              std::string(f.path) + "/" + r->header[0] + ": '" + r->header[0] + "' is not " + f.what +
                  " Radioss knows" + (suggestion.empty() ? "" : " (" + suggestion + ")") +
                  "; radx writes: " + accepted_anim_names(f.path) + " (docs/results.md)");
        continue;
      }
      if (!a) {
        warning(*r, Diag::OutputNotWritten,
                std::string(f.path) + "/" + r->header[0] + ": '" + r->header[0] + "' is not " + f.what +
                    " radx writes; the run goes on without it; radx writes: " + accepted_anim_names(f.path) +
                    " (docs/results.md)");
        continue;
      }
      if (r->header.size() > 1) {
        std::string extra;
        for (std::size_t k = 1; k < r->header.size(); ++k) extra += "/" + r->header[k];
        warning(*r, Diag::OutputNotWritten,
                std::string(f.path) + "/" + r->header[0] + extra + ": radx writes " + std::string(f.path) +
                    "/" + std::string(a->name) + " only, without further fields ('" + extra.substr(1) +
                    "' is not written); the run goes on without it (docs/results.md)");
        continue;
      }
      if (std::find(f.out->begin(), f.out->end(), a->name) == f.out->end()) f.out->emplace_back(a->name);
    }
  }
}

void Builder::time_steps(model::RunControls& rc) {
  rc.global = model::DtControl{};
  rc.global.action = model::DtAction::Stop;
  if (const EngineRecord* r = single("/DT"))
    read_dt(*r, rc.global, kDefaultScale, 0.0, model::DtAction::Stop);
  step_bounds(rc);
  element_time_steps(rc);
  nodal_time_step(rc);
  interface_time_step(rc);
}

// /DTIX: the first step and the largest one.
void Builder::step_bounds(model::RunControls& rc) {
  const EngineRecord* r = single("/DTIX");
  if (!r) return;
  const double ini = r->value(0, 0), mx = r->value(0, 1);
  if (ini < 0)
    error(*r, Diag::ValueOutOfRange, "DT_ini = " + num(ini) + " is negative; accepted: >= 0 (0: no bound)");
  if (mx < 0)
    error(*r, Diag::ValueOutOfRange,
          "DT_max = " + num(mx) + " is negative; accepted: > 0, or 0 for no bound");
  if (mx > 0 && ini > mx)
    error(*r, Diag::InconsistentValues,
          "DT_ini = " + num(ini) + " is above DT_max = " + num(mx) +
              ": the first step cannot exceed the largest");
  rc.dt_initial = std::max(0.0, ini);
  rc.dt_max = mx > 0 ? mx : 1e30;
}

// /DT/BRICK, /DT/SHELL, /DT/SH_3N with /CST or /STOP (one of them), /DT/SPRING/STOP: each element family's
// control, the global one unless given. /STOP (OpenRadioss: IDTMIN 1 of the family) stops the run when an
// element of the family has a scaled step below Tmin.
void Builder::element_time_steps(model::RunControls& rc) {
  struct Fam {
    std::string_view path, stop;
    model::DtControl* c;
  };
  for (const Fam f :
       {Fam{"/DT/BRICK/CST", "/DT/BRICK/STOP", &rc.brick}, Fam{"/DT/SHELL/CST", "/DT/SHELL/STOP", &rc.shell},
        Fam{"/DT/SH_3N/CST", "/DT/SH_3N/STOP", &rc.shell3}, Fam{{}, "/DT/SPRING/STOP", &rc.spring}}) {
    *f.c = rc.global;
    f.c->given = false;
    const EngineRecord* stop = single(f.stop);
    const EngineRecord* cst = f.path.empty() ? nullptr : single(f.path);
    if (stop && cst) {
      const Where first = deck_.where(cst->pos);
      error(*stop, Diag::InconsistentValues,
            std::string(f.stop) + " and " + std::string(f.path) + " (" + std::string(first.file) + ":" +
                std::to_string(first.line) +
                ") are both given; give one action for the family's minimum step");
    } else if (stop) {
      read_dt(*stop, *f.c, rc.global.scale, 0.0, model::DtAction::Stop);
      if (!(f.c->t_min > 0))
        warning(*stop, Diag::ValueOutOfRange,
                std::string(f.stop) + " with Tmin = 0 never stops the run; give the minimum step");
    }
    if (const EngineRecord* r = cst) {
      read_dt(*r, *f.c, rc.global.scale, rc.global.t_min, model::DtAction::Constant);
      if (f.path == "/DT/BRICK/CST" && r->lines.size() > 1 &&
          std::any_of(r->lines[1].begin(), r->lines[1].end(), [](double x) { return x != 0; }))
        warning(*r, Diag::UnimplementedOption,
                "COL_min and DEFV_min (second line) are not used by radx: bricks switch to small strain at "
                "Tmin only");
    }
  }
}

// /DT/NODA (no action at Tmin) or /DT/NODA/CST (mass added below Tmin, up to %AddedMass), not both.
void Builder::nodal_time_step(model::RunControls& rc) {
  rc.nodal = model::DtControl{};
  if (const EngineRecord* r = single("/DT/NODA")) {
    // The action comes in the header: /DT/NODA/STOP reaches this declaration too (a text option).
    std::int64_t option = 0;
    if (!r->header.empty() && parse_int(r->header[0], option) != NumberStatus::Ok)
      diags_.error(Diag::UnsupportedKeyword, deck_.where(r->pos, 1), About{r->decl->path},
                   "/DT/NODA/" + r->header[0] +
                       ": a nodal time step with that action changes the results and radx cannot run it; "
                       "radx runs /DT/NODA (no action at Tmin) and /DT/NODA/CST (mass added below Tmin)");
    else if (option != 0)
      error(*r, Diag::ValueOutOfRange,
            "/DT/NODA/" + std::to_string(option) +
                ": the option is 0 or blank (a node group is read only by "
                "/DT/NODA/CST/1)");
    else
      read_dt(*r, rc.nodal, kDefaultScale, 0.0, model::DtAction::None);
  }
  const EngineRecord* r = single("/DT/NODA/CST");
  if (!r) return;
  if (rc.nodal.given)
    error(*r, Diag::DuplicateSingleton, "/DT/NODA and /DT/NODA/CST are both given; give one nodal time step");
  read_dt(*r, rc.nodal, kDefaultScale, 0.0, model::DtAction::AddMass);
  const double pct = r->value(0, 2);
  if (pct < 0)
    error(*r, Diag::ValueOutOfRange,
          "%AddedMass = " + num(pct) +
              " is negative; give the added-mass percentage that stops the run "
              "(0: no limit)");
  else
    rc.nodal_max_added_mass_pct = pct;
  std::int64_t option = 0;
  if (header_int(*r, 0, 0, option)) {
    if (option != 0 && option != 1)
      error(*r, Diag::ValueOutOfRange,
            "/DT/NODA/CST/" + std::to_string(option) + ": the option is 0 or 1 (1: a node group follows)");
    const double grnod = r->value(1, 0);
    if (option == 1 && grnod != 0)
      error(*r, Diag::UnimplementedOption,
            "grnod_ID = " + num(grnod) +
                ": radx applies the nodal time step to every node; restricting it to a node group is not "
                "implemented (remove the option /1 and the group line)");
  }
}

// /DT/INTER/DEL (which has precedence), /DT/INTER/CST, /DT/INTER/LAG or /DT/INTER/STOP (one of the last
// three).
void Builder::interface_time_step(model::RunControls& rc) {
  rc.inter = model::DtControl{};
  const EngineRecord* cst = single("/DT/INTER/CST");
  const EngineRecord* del = single("/DT/INTER/DEL");
  const EngineRecord* lag = single("/DT/INTER/LAG");
  const EngineRecord* stop = single("/DT/INTER/STOP");
  if (stop && !del) {
    for (const EngineRecord* other : {cst, lag}) {
      if (!other) continue;
      const Where first = deck_.where(other->pos);
      error(*stop, Diag::InconsistentValues,
            "/DT/INTER/STOP and " + other->written + " (" + std::string(first.file) + ":" +
                std::to_string(first.line) +
                ") are both given; give one action for the interface minimum step");
      return;
    }
    read_dt(*stop, rc.inter, kDefaultScale, 0.0, model::DtAction::Stop);
    if (!(rc.inter.t_min > 0))
      warning(*stop, Diag::ValueOutOfRange,
              "/DT/INTER/STOP with Tmin = 0 never stops the run; give the minimum step");
    return;
  }
  if (del) {
    read_dt(*del, rc.inter, kDefaultScale, 0.0, model::DtAction::Delete);
    for (const EngineRecord* other : {cst, lag, stop})
      if (other)
        warning(*other, Diag::InconsistentValues,
                other->written +
                    " is ignored: /DT/INTER/DEL is also given and has precedence for the "
                    "interface time step");
  } else if (cst && lag) {
    const Where first = deck_.where(cst->pos);
    error(*lag, Diag::InconsistentValues,
          "/DT/INTER/LAG and /DT/INTER/CST (" + std::string(first.file) + ":" + std::to_string(first.line) +
              ") are both given; give one (for /INTER/LAGDT/TYPE7 both switch pairs to Lagrange "
              "multipliers; for /INTER/TYPE7, CST adds mass)");
  } else if (cst) {
    read_dt(*cst, rc.inter, kDefaultScale, 0.0, model::DtAction::AddMass);
  } else if (lag) {
    read_dt(*lag, rc.inter, kDefaultScale, 0.0, model::DtAction::Lagrange);
  }
}

void Builder::stop(model::RunControls& rc) {
  const EngineRecord* r = single("/STOP");
  if (!r || r->lines.empty()) return;
  const char* names[] = {"Emax", "Mmax", "Nmax"};
  double* out[] = {&rc.stop_energy_error_pct, &rc.stop_mass_error, &rc.stop_nodal_mass_error};
  for (std::size_t k = 0; k < 3; ++k) {
    const double v = r->value(0, k);
    if (v < 0)
      error(*r, Diag::ValueOutOfRange,
            std::string(names[k]) + " = " + num(v) + " is negative; give >= 0 (0: off)");
    else
      *out[k] = v > 0 ? v : kOff;
  }
  const char* flags[] = {"NTH", "NANIM", "NERR_POSIT"};
  bool* fout[] = {&rc.stop_writes_th, &rc.stop_writes_anim, &rc.stop_positive_error_only};
  for (std::size_t k = 0; k < 3; ++k) {
    const double v = r->value(0, 3 + k);
    if (v != 0 && v != 1)
      error(*r, Diag::ValueOutOfRange, std::string(flags[k]) + " = " + num(v) + ": give 0 or 1");
    else
      *fout[k] = v == 1;
  }
}

void Builder::rbodies(model::RunControls& rc) {
  std::map<std::int64_t, const EngineRecord*> on;
  for (const auto* path : {"/RBODY/ON", "/RBODY/OFF"}) {
    const bool is_on = std::string_view(path) == "/RBODY/ON";
    for (const EngineRecord* r : read_of(path)) {
      if (r->ids.empty())
        warning(*r, Diag::EmptyRecordList, std::string(path) + " lists no rigid-body id: it does nothing");
      for (std::size_t k = 0; k < r->ids.size(); ++k) {
        const std::int64_t id = r->ids[k];
        // Radioss passes over an id 0 (decks write /RBODY/ON then 0 to switch nothing) and over any id that
        // names no rigid body; ids the model lacks are checked against it by check_rigid_body_switches.
        const Where at = deck_.where(k < r->id_pos.size() ? r->id_pos[k] : r->pos, 1);
        if (id == 0) {
          diags_.note(Diag::ValueOutOfRange, at, About{path},
                      std::string(path) + " lists rigid-body id 0, which switches nothing (as in Radioss)");
          continue;
        }
        if (id < 0) {
          diags_.warning(
              Diag::ValueOutOfRange, at, About{path},
              std::string(path) + " lists rigid-body id " + std::to_string(id) +
                  ", which names no rigid body (ids are > 0): it switches nothing, and the run goes "
                  "on (as in Radioss)");
          continue;
        }
        if (is_on) {
          on.emplace(id, r);
          rc.rbody_on.push_back(id);
        } else {
          if (on.count(id)) {
            const Where first = deck_.where(on[id]->pos);
            error(*r, Diag::InconsistentValues,
                  "rigid body " + std::to_string(id) + " is both switched on (" + std::string(first.file) +
                      ":" + std::to_string(first.line) + ") and off in this run");
          }
          rc.rbody_off.push_back(id);
        }
      }
    }
  }
}

void Builder::versions() {
  for (const auto* path : {"/VERS", "/ANIM/VERS"}) {
    if (const EngineRecord* r = single(path)) {
      std::int64_t v = 0;
      if (header_int(*r, 0, 0, v) && v < 0)
        error(*r, Diag::ValueOutOfRange, "version " + std::to_string(v) + " must be >= 0");
    }
  }
}

model::RunControls Builder::build() {
  model::RunControls rc;
  run(rc);
  print(rc);
  tfile(rc);
  anim_dt(rc);
  anim_names(rc);
  time_steps(rc);
  stop(rc);
  rbodies(rc);
  versions();
  return rc;
}

}  // namespace

const std::vector<AnimFieldName>& anim_field_names() {
  // Significant letters and exclusions as the Radioss animation reader compares them.
  static const std::vector<AnimFieldName> table = {
      {"/ANIM/ELEM", "VONM", {}, "von_mises", "von Mises stress", 4, {}},
      {"/ANIM/ELEM", "EPSP", {}, "plastic_strain", "equivalent plastic strain", 4, {}},
      {"/ANIM/ELEM", "THIC", {}, "thickness", "current shell thickness (0 for solids)", 4, {}},
      {"/ANIM/ELEM", "ENER", {}, "internal_energy_density", "internal energy per unit volume", 4, {}},
      {"/ANIM/ELEM", "P", {}, "pressure", "pressure -trace(stress)/3", 1, {"PLA51"}},
      {"/ANIM/ELEM", "DENS", {}, "density", "current density", 4, {"DENS3"}},
      {"/ANIM/ELEM", "HOUR", {}, "hourglass_energy_density", "hourglass energy per unit volume", 4, {}},
      {"/ANIM/VECT", "VEL", {}, "velocity", "nodal velocity", 3, {}},
      {"/ANIM/VECT", "DISP", {"DIS"}, "displacement", "nodal displacement", 3, {}},
      {"/ANIM/VECT", "ACC", {}, "acceleration", "nodal acceleration", 3, {}},
      {"/ANIM/VECT", "CONT", {}, "contact_force", "penalty and Lagrange contact forces", 4, {"CONT2"}},
      {"/ANIM/VECT", "FINT", {}, "internal_force", "nodal internal forces", 4, {}},
      {"/ANIM/VECT", "FEXT", {}, "external_force", "nodal external forces", 4, {}},
      {"/ANIM/VECT", "FREAC", {}, "reaction_force", "reaction forces of kinematic conditions", 5, {}},
      {"/ANIM/TENS", "STRESS", {}, "stress", "stress tensor XX YY ZZ XY YZ XZ", 6, {}},
      {"/ANIM/NODA", "DMAS", {}, "added_mass", "mass added by /DT/NODA/CST and /DT/INTER/CST", 4, {}},
      {"/ANIM/NODA", "DT", {}, "nodal_time_step", "nodal time step", 2, {}},
  };
  return table;
}

namespace {

// The /ANIM field names the Radioss engine knows (its animation reader, read in OpenRadioss), as the
// beginnings it compares: a written name that starts with one of them is a Radioss field. `exact` names
// must be written whole (DT, not DTX). /ANIM/ELEM's P and K are compared on their first letter alone by
// Radioss too (any P... but PLA51 is the pressure, any K... the turbulent energy), so no name starting with
// them is a misspelling there.
struct RadiossAnimName {
  std::string_view family;
  std::string_view name;
  bool exact = false;
};

const std::vector<RadiossAnimName>& radioss_anim_names() {
  static const std::vector<RadiossAnimName> table = [] {
    std::vector<RadiossAnimName> t;
    auto add = [&t](std::string_view family, std::initializer_list<std::string_view> names) {
      for (auto n : names) t.push_back({family, n});
    };
    add("/ANIM/VECT", {"ACC",  "CLUST", "CONT",  "CONT2", "DIS",   "DROT",  "DXANC", "FEXT",   "FINT",
                       "FOPT", "FREAC", "FRES",  "FVEL",  "GVEL",  "MREAC", "PCONT", "PCONT2", "VEL",
                       "VFLU", "VROT",  "ZFINT", "ZFP",   "ZFVEL", "ZMOM",  "ZVEL"});
    add("/ANIM/TENS", {"EPSDO", "STRAI", "STRESS"});
    add("/ANIM/ELEM",
        {"AMS",  "BF51",  "BFRAC", "BULK",  "COLOR", "DAM1",      "DAM2",    "DAM3",    "DAMG",
         "DENS", "DENS3", "DOMAI", "EINT",  "ENER",  "EPSD",      "EPSP",    "FIN",     "|FIN|",
         "HOUR", "K",     "LAW20", "LAW51", "MACH",  "MOM",       "|MOM|",   "NL_EPSD", "NL_EPSP",
         "OFF",  "P",     "PLA51", "QVIS",  "SCHLI", "SIGEQ",     "SIGX",    "SIGY",    "SIGZ",
         "SSP",  "TDET",  "TEM51", "TEMP",  "THIC",  "TILLOTSON", "TSAIWU",  "TVIS",    "USER",
         "USR",  "VEL",   "|VEL|", "VFRAC", "VOL",   "VORT",      "VSTRAIN", "WPLA"});
    add("/ANIM/NODA", {"DAMA2", "DENS", "DINER", "DMAS", "ENER", "FPOT", "NDMAS", "NVAR", "PEXT", "SCHLI",
                       "SSP", "STIF", "TEMP", "VFRAC", "ZVFRA", "ZVOL"});
    t.push_back({"/ANIM/ELEM", "DT", true});
    t.push_back({"/ANIM/NODA", "DT"});
    t.push_back({"/ANIM/NODA", "P", true});
    return t;
  }();
  return table;
}

}  // namespace

bool radioss_knows_anim_field(std::string_view family, std::string_view written) {
  const std::string w = upper(written);
  for (const auto& n : radioss_anim_names())
    if (n.family == family && (n.exact ? w == n.name : w.starts_with(n.name))) return true;
  return false;
}

std::vector<std::string> anim_names_of_family(std::string_view family) {
  std::vector<std::string> names;
  for (const auto& a : anim_field_names())
    if (a.family == family) names.emplace_back(a.name);
  for (const auto& n : radioss_anim_names())
    if (n.family == family && std::find(names.begin(), names.end(), n.name) == names.end())
      names.emplace_back(n.name);
  return names;
}

const AnimFieldName* find_anim_field(std::string_view family, std::string_view written) {
  const std::string w = upper(written);
  auto starts_with = [&w](std::string_view p) {
    return w.size() >= p.size() && w.compare(0, p.size(), p) == 0;
  };
  for (const auto& a : anim_field_names()) {
    if (a.family != family) continue;
    if (a.name == w) return &a;
    for (auto alias : a.aliases)
      if (alias == w) return &a;
  }
  for (const auto& a : anim_field_names()) {
    if (a.family != family || a.significant == 0) continue;
    if (!starts_with(a.name.substr(0, a.significant))) continue;
    if (std::any_of(a.excluded.begin(), a.excluded.end(), starts_with)) continue;
    return &a;
  }
  return nullptr;
}

std::string accepted_anim_names(std::string_view family) {
  std::string out;
  for (const auto& a : anim_field_names()) {
    if (a.family != family) continue;
    if (!out.empty()) out += ' ';
    out += a.name;
    for (auto alias : a.aliases) out += " (" + std::string(alias) + ")";
  }
  return out;
}

model::RunControls build_run_controls(const EngineDeck& deck, Diagnostics& diags) {
  return Builder(deck, diags).build();
}

void check_run_name(const EngineDeck& deck, const model::RunControls& controls,
                    const std::string& engine_deck_path, Diagnostics& diags) {
  const auto runs = deck.of("/RUN");
  if (runs.empty()) return;
  const EngineRecord& r = *runs.front();
  int number = -1;
  const std::string root = model::split_run_suffix(engine_deck_path, number);
  const std::string file = std::filesystem::path(engine_deck_path).filename().string();
  if (!controls.run_name.empty() && upper(controls.run_name) != upper(root)) {
    diags.warning(Diag::EngineRunNameMismatch, deck.where(r.pos, 1), About{"/RUN"},
                  "the /RUN name " + controls.run_name + " differs from the root " + root +
                      " of the file name " + file + "; radx names the outputs after the file (" + root +
                      "_0001.out, " + root + "_summary.json)");
  }
  if (number > 0 && number != controls.run_number) {
    diags.warning(Diag::EngineRunNameMismatch, deck.where(r.pos, 1), About{"/RUN"},
                  "the /RUN number " + std::to_string(controls.run_number) + " differs from the run number " +
                      std::to_string(number) + " of the file name " + file);
  }
}

// Run 2 and later resume run 1 from its restart file in Radioss. radx writes no restart file yet, so such a
// run could only start again from cycle 0 under run 1's name, over run 1's outputs: it is refused before the
// engine claims the output folder, and run 1's files stay as they are.
void refuse_restart_run(const EngineDeck& deck, const EngineRecord& r, const model::RunControls& rc,
                        Diagnostics& diags) {
  diags.error(Diag::UnimplementedOption, deck.where(r.pos, 1), About{"/RUN"},
              "run number " + std::to_string(rc.run_number) +
                  " is a restart run: Radioss resumes it from the restart file of the run before, and radx "
                  "writes no restart file yet, so it cannot resume; radx runs run 1 only (" +
                  (rc.run_name.empty() ? std::string("NAME") : rc.run_name) +
                  "_0001.rad with /RUN/name/1). Nothing was run and no output was touched");
}

model::RunControls read_run_controls(const std::string& engine_deck_path, Diagnostics& diags,
                                     EngineDeck* deck) {
  EngineDeck read = read_engine_deck(engine_deck_path, diags);
  model::RunControls rc;
  if (!read.records.empty()) {
    rc = build_run_controls(read, diags);
    // /RUN/name without irun, or with irun 0: the Radioss engine takes the run number from the file name
    // (and ignores the /RUN number even when one is given, with a warning radx gives as RX803).
    const auto runs = read.of("/RUN");
    int file_number = -1;
    model::split_run_suffix(engine_deck_path, file_number);
    if (!runs.empty()) {
      const EngineRecord& r = *runs.front();
      std::int64_t irun = -1;
      const bool zero = r.header.size() >= 2 && parse_int(r.header[1], irun) == NumberStatus::Ok && irun == 0;
      if (r.header.size() < 2 || zero) rc.run_number = file_number > 0 ? file_number : 1;
      if (zero) {
        diags.note(Diag::DefaultApplied, read.where(r.pos, 1), About{"/RUN"},
                   "run number 0: the run takes the number " + std::to_string(rc.run_number) +
                       (file_number > 0 ? " of the file name" : " (the file name carries none)") +
                       ", as the Radioss engine does");
      }
    }
    check_run_name(read, rc, engine_deck_path, diags);
    if (!runs.empty() && rc.run_number >= 2) refuse_restart_run(read, *runs.front(), rc, diags);
  }
  if (deck) *deck = std::move(read);
  return rc;
}

void check_rigid_body_switches(const EngineDeck& deck, std::span<const std::int64_t> model_rigid_body_ids,
                               model::RunControls& controls, Diagnostics& diags) {
  auto known = [&](std::int64_t id) {
    return std::find(model_rigid_body_ids.begin(), model_rigid_body_ids.end(), id) !=
           model_rigid_body_ids.end();
  };
  for (const auto* path : {"/RBODY/ON", "/RBODY/OFF"}) {
    for (const EngineRecord* r : deck.of(path)) {
      for (std::size_t k = 0; k < r->ids.size(); ++k) {
        const std::int64_t id = r->ids[k];
        if (id <= 0 || known(id)) continue;  // ids <= 0 were reported by build_run_controls
        const SourcePos at = k < r->id_pos.size() ? r->id_pos[k] : r->pos;
        diags.warning(Diag::MissingReference, deck.where(at, 1), About{path},
                      std::string(path) + " names rigid body " + std::to_string(id) +
                          ", which the model does not have: it switches nothing, and the run goes on (as in "
                          "Radioss)");
      }
    }
  }
  for (auto* list : {&controls.rbody_on, &controls.rbody_off})
    std::erase_if(*list, [&](auto id) { return !known(id); });
}

}  // namespace radx
