// The engine deck's keywords as data (shared/spec/deck-format.md section 3). Data lines are free format;
// each line declares the names of its values in order, how many of them must be present, and their
// dimensions. Paths are written in full; the reader applies the engine's 5-character truncation of keyword
// fields when it matches them.
#include "parser/keyword_schema.hpp"

namespace radx::schema {

namespace {

// Control cards that change no physics in radx: accepted, echoed as ignored.
EngineKeywordDecl ignored(EngineKeywordDecl k) {
  k.support = Support::Ignored;
  return k;
}

EngineKeywordDecl ekw(std::string_view path, std::string_view meaning) {
  EngineKeywordDecl k;
  k.path = path;
  k.meaning = meaning;
  return k;
}

EngineLineDecl line(std::vector<std::string_view> names, std::size_t required, std::vector<Dim> dims = {}) {
  EngineLineDecl l;
  l.names = std::move(names);
  l.required = required;
  l.dims = std::move(dims);
  return l;
}

// The two values every /DT line carries.
EngineLineDecl dt_line() {
  return line({"Tscale", "Tmin"}, 2, {dim::none, dim::time});
}

}  // namespace

const std::vector<EngineKeywordDecl>& engine_keywords() {
  static const std::vector<EngineKeywordDecl> table = [] {
    std::vector<EngineKeywordDecl> t;
    {
      auto k = ekw("/RUN", "run name and number, and the end time of the run");
      k.header_fields = {"name", "irun", "letter"};
      k.header_required = 2;
      k.lines = {line({"Tstop"}, 1, {dim::time})};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/VERS", "engine input version");
      k.header_fields = {"version"};
      k.header_required = 1;
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/TFILE", "time-history file format and output interval");
      k.header_fields = {"ityp"};
      k.lines = {line({"dt_his"}, 1, {dim::time})};
      t.push_back(std::move(k));
    }
    {
      auto k =
          ekw("/ANIM/DT", "animation output: start time, interval, optional end time, frame count, function");
      k.lines = {line({"Tstart", "dT", "Tstop", "Nframes", "fct_ID"}, 2,
                      {dim::time, dim::time, dim::time, dim::none, dim::none})};
      t.push_back(std::move(k));
    }
    auto anim_field = [&t](std::string_view path, std::string_view meaning) {
      auto k = ekw(path, meaning);
      k.header_fields = {"name"};
      k.header_required = 1;
      k.prefix_match = true;
      t.push_back(std::move(k));
    };
    anim_field("/ANIM/ELEM", "element scalar field written to the animation files");
    anim_field("/ANIM/VECT", "nodal vector field written to the animation files");
    anim_field("/ANIM/TENS", "element tensor field written to the animation files");
    anim_field("/ANIM/NODA", "nodal scalar field written to the animation files");
    t.push_back(ignored(ekw("/ANIM/GZIP", "gzip-compressed animation files (radx writes HDF5 states)")));
    {
      auto k = ekw("/ANIM/VERS", "animation file format version");
      k.header_fields = {"version"};
      k.header_required = 1;
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT", "global element time-step scale and minimum");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/NODA/CST", "nodal time step with mass added below the minimum");
      k.header_fields = {"option"};
      k.lines = {line({"Tscale", "Tmin", "%AddedMass"}, 2, {dim::none, dim::time, dim::none}),
                 line({"grnod_ID"}, 0)};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/INTER/CST", "interface time step kept at the minimum by added mass (LAGDT: switch)");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/INTER/DEL",
                   "secondary nodes whose interface time step falls below the minimum are removed");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/INTER/LAG", "LAGDT pairs below the minimum time step switch to Lagrange multipliers");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/BRICK/CST", "bricks below the minimum time step switch to small strain");
      k.header_fields = {"option"};
      k.lines = {dt_line(), line({"COL_min", "DEFV_min"}, 0)};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/SHELL/CST", "4-node shells below the minimum time step switch to small strain");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/SH_3N/CST", "3-node shells below the minimum time step switch to small strain");
      k.aliases = {"/DT/SH3N/CST"};
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k =
          ekw("/PRINT", "listing line frequency (negative: also to standard output) and header frequency");
      k.header_fields = {"n", "nh"};
      k.header_required = 1;
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/STOP", "stop criteria on energy error and mass errors");
      k.lines = {line({"Emax", "Mmax", "Nmax", "NTH", "NANIM", "NERR_POSIT"}, 3)};
      t.push_back(std::move(k));
    }
    {
      auto k = ignored(ekw("/RFILE", "restart file frequency in cycles (radx writes no restart files)"));
      k.header_fields = {"n"};
      k.lines = {line({"Ncycle"}, 1)};
      t.push_back(std::move(k));
    }
    t.push_back(ignored(ekw("/RFILE/OFF", "no restart files")));
    t.push_back(ignored(ekw("/MON/ON", "CPU and memory monitoring report (radx always prints its cost)")));
    t.push_back(ignored(ekw("/MON/OFF", "CPU and memory monitoring report off")));
    t.push_back(
        ignored(ekw("/PARITH/ON", "parallel arithmetic on (radx results never depend on the thread count)")));
    t.push_back(
        ignored(ekw("/PARITH/OFF", "parallel arithmetic off (radx keeps results independent of threads)")));
    {
      auto k = ekw("/RBODY/ON", "activate the listed rigid bodies");
      k.id_lines = true;
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/RBODY/OFF", "deactivate the listed rigid bodies");
      k.id_lines = true;
      t.push_back(std::move(k));
    }
    t.push_back(ekw("/END/ENGINE", "end of the engine part of a one-file deck"));
    t.push_back(ekw("/END", "end of the engine deck"));
    return t;
  }();
  return table;
}

}  // namespace radx::schema
