// The engine deck's keywords as data (docs/theory/deck-format.md section 3). Data lines are free format;
// each line declares the names of its values in order, how many of them must be present, and their
// dimensions. Paths are written in full; the reader applies the engine's 5-character truncation of keyword
// fields when it matches them.
//
// Every keyword the Radioss engine reads is declared here (its keyword table and readers, engine/source/input
// of OpenRadioss), each in one of four classes:
// * Read: radx reads and runs it;
// * Ignored: it changes no result in radx (titles, processors, monitoring, restart files, file formats): a
//   note says what is ignored and why;
// * NotWritten: an output request for a file or field radx does not write (H3D, /OUTP, /STATE, other
//   /ANIM fields): a warning, and the run goes on;
// * Unsupported: it changes the results and radx cannot run it (deletion, imposed velocities, relaxation,
//   damping, other time-step controls): an error naming what radx would need.
// A keyword whose first field Radioss does not know is an unknown keyword (Radioss stops on it too).
#include "parser/keywords/keyword_schema.hpp"

namespace radx::schema {

namespace {

EngineKeywordDecl ekw(std::string_view path, std::string_view meaning) {
  EngineKeywordDecl k;
  k.path = path;
  k.meaning = meaning;
  return k;
}

// A control card that changes no result in radx; `why` says why (shown in the note). It keeps the
// declaration's lines (read, never checked) and takes any further fields.
EngineKeywordDecl ignored(EngineKeywordDecl k, std::string_view why) {
  k.support = Support::Ignored;
  k.reason = why;
  return k;
}
EngineKeywordDecl ignored(std::string_view path, std::string_view meaning, std::string_view why) {
  auto k = ignored(ekw(path, meaning), why);
  k.prefix_match = true;
  return k;
}

// An output request radx does not write; `instead` says what radx writes (shown in the warning).
EngineKeywordDecl not_written(std::string_view path, std::string_view meaning, std::string_view instead) {
  auto k = ekw(path, meaning);
  k.support = Support::NotWritten;
  k.reason = instead;
  k.prefix_match = true;
  return k;
}

// A keyword that changes the results and that radx cannot run; `needs` says what radx would need.
EngineKeywordDecl unsupported(std::string_view path, std::string_view meaning, std::string_view needs) {
  auto k = ekw(path, meaning);
  k.support = Support::Unsupported;
  k.reason = needs;
  k.prefix_match = true;
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
      auto k =
          ekw("/RUN", "run name and number (from the file name when absent), and the end time of the run");
      k.header_fields = {"name", "irun", "letter"};
      k.header_required = 1;
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
      auto k = ekw("/TFILE", "time-history file format and output interval (0: every cycle)");
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
    t.push_back(ignored(ekw("/ANIM/GZIP", "gzip-compressed animation files"),
                        "radx writes its animation states in HDF5 (docs/results.md)"));
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
      // /DT/NODA and /DT/NODA/0: OpenRadioss's freform.F leaves the action at none (IDT 0).
      auto k = ekw("/DT/NODA", "nodal time step as the run's step, no action at the minimum");
      k.header_fields = {"option"};
      k.lines = {line({"Tscale", "Tmin"}, 1, {dim::none, dim::time})};
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
      auto k = ekw("/DT/INTER/STOP", "the run stops when an interface time step falls below the minimum");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/SPRING/STOP",
                   "spring time-step scale; the run stops when a spring's step falls below "
                   "the minimum");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/BRICK/STOP",
                   "brick time-step scale; the run stops when a brick's step falls below the "
                   "minimum");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/SHELL/STOP",
                   "4-node shell time-step scale; the run stops when a shell's step falls "
                   "below the minimum");
      k.lines = {dt_line()};
      t.push_back(std::move(k));
    }
    {
      auto k = ekw("/DT/SH_3N/STOP",
                   "3-node shell time-step scale; the run stops when a 3-node shell's step "
                   "falls below the minimum");
      k.aliases = {"/DT/SH3N/STOP"};
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
      auto k = ignored(ekw("/RFILE", "restart file frequency in cycles"),
                       "radx writes no restart files; they change no result");
      k.header_fields = {"n"};
      k.lines = {line({"Ncycle"}, 1)};
      t.push_back(std::move(k));
    }
    t.push_back(ignored(ekw("/RFILE/OFF", "no restart files"), "radx writes no restart files"));
    t.push_back(ignored(ekw("/MON/ON", "CPU and memory monitoring report"),
                        "radx prints its cost in microseconds per element per cycle in every listing"));
    t.push_back(ignored(ekw("/MON/OFF", "CPU and memory monitoring report off"),
                        "radx prints its cost in microseconds per element per cycle in every listing"));
    t.push_back(ignored("/MON", "other monitoring reports (FULL, SYNC, MAT)",
                        "monitoring only measures the run; radx prints its cost in every listing"));
    t.push_back(ignored(ekw("/PARITH/ON", "parallel arithmetic on"),
                        "radx results never depend on the thread count"));
    t.push_back(ignored(ekw("/PARITH/OFF", "parallel arithmetic off"),
                        "radx keeps its results independent of the thread count whatever the deck says"));
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
    // Control cards that change no result in radx.
    t.push_back(ignored("/TITLE", "run title, on the next line, printed in the Radioss listing",
                        "radx names the run by /RUN and its file; a title changes no result"));
    t.push_back(ignored("/PROC", "number of processors of the run",
                        "radx takes its threads from --threads or OMP_NUM_THREADS and its results do not "
                        "depend on them"));
    t.push_back(ignored("/SPMD", "domain decomposition of the MPI engine",
                        "radx runs threads in one process; the decomposition changes no result"));
    t.push_back(ignored("/PERF", "contact sorting algorithm, for speed",
                        "radx has its own contact search; the sorting algorithm only changes the speed"));
    t.push_back(ignored("/PROFILE", "MPI profiling report",
                        "radx prints its cost in microseconds per element per cycle in every listing"));
    t.push_back(ignored("/DEBUG", "debugging printouts of the engine", "they only print information"));
    t.push_back(ignored("/TH/VERS", "time-history file format version",
                        "radx writes its time history in HDF5 (NAME_th.h5)"));
    t.push_back(ignored("/TH/TITLE", "variable titles in the time-history file",
                        "radx names every time-history variable in NAME_th.h5"));
    t.push_back(ignored("/SHVER", "shell version flag, read and not used by the Radioss engine",
                        "the Radioss engine does nothing with it either"));
    t.push_back(ignored("/ANIM/COMP", "compressed animation files",
                        "radx writes its animation states in HDF5 (docs/results.md)"));
    t.push_back(ignored("/DTSDE/OFF", "the standard time step for degenerated bricks (the default)",
                        "it is the default, which radx uses"));

    // Output requests radx does not write: a warning, and the run goes on.
    constexpr std::string_view kAnimInstead =
        "radx writes /ANIM/ELEM, /ANIM/VECT, /ANIM/TENS/STRESS and /ANIM/NODA fields, for every element, in "
        "its HDF5 states";
    t.push_back(
        not_written("/ANIM/SHELL", "shell fields and tensors by layer in the animation files",
                    "radx writes the shells' stress and von Mises at the bottom, middle and top layers "
                    "(stress_bottom, stress_middle, stress_top for LOWER, the mid-surface and UPPER; "
                    "von_mises_bottom, ...) and the stress at every point through the thickness "
                    "(stress_point_1 at the bottom, ...) with /ANIM/TENS/STRESS and /ANIM/ELEM/VONM "
                    "(docs/results.md)"));
    t.push_back(not_written("/ANIM/BRICK", "brick fields and tensors in the animation files", kAnimInstead));
    t.push_back(not_written("/ANIM/MASS", "masses in the animation files",
                            "radx writes the mass added to nodes (/ANIM/NODA/DMAS)"));
    t.push_back(not_written("/ANIM",
                            "other animation output (beams, springs, Gauss points, cuts, sensor-triggered or "
                            "titled frames, material and element numbers)",
                            kAnimInstead));
    t.push_back(not_written("/OUTP", "Radioss ASCII state files (NAMEnnnY)",
                            "radx writes HDF5 states (/ANIM) and an HDF5 time history (/TFILE)"));
    t.push_back(not_written("/H3D", "H3D result files", "radx writes HDF5 states for ParaView (/ANIM)"));
    t.push_back(not_written("/STATE", "state files of the deformed model (NAME_nnnSTA)",
                            "radx writes HDF5 states (/ANIM)"));
    t.push_back(not_written("/DYNAIN", "LS-DYNA dynain file of the deformed model",
                            "radx writes HDF5 states (/ANIM)"));
    {
      auto k = not_written("/ABF", "ABF time-history files", "radx writes an HDF5 time history (/TFILE)");
      k.aliases = {"/AABF", "/BABF", "/CABF", "/DABF", "/EABF", "/FABF", "/GABF", "/HABF", "/IABF"};
      t.push_back(std::move(k));
    }
    {
      auto k = not_written("/ATFILE", "additional time-history files with their own interval",
                           "radx writes one HDF5 time history at the /TFILE interval");
      k.aliases = {"/BTFILE", "/CTFILE", "/DTFILE", "/ETFILE", "/FTFILE", "/GTFILE", "/HTFILE", "/ITFILE"};
      t.push_back(std::move(k));
    }
    t.push_back(not_written("/@TFILE", "noise (acoustic) output file",
                            "radx writes nodal velocities and accelerations in its states (/ANIM/VECT)"));
    t.push_back(not_written("/REPORT", "HTML or HyperView report of the run",
                            "radx writes its listing and NAME_summary.json"));

    // Keywords that change the results and that radx cannot run: an error naming what radx would need.
    t.push_back(unsupported("/DT/AMS", "advanced mass scaling",
                            "radx would need the non-diagonal AMS mass matrix and its iterative solve"));
    t.push_back(unsupported("/DT/CST_AMS", "nodal added mass together with advanced mass scaling",
                            "radx would need the non-diagonal AMS mass matrix and its iterative solve"));
    t.push_back(unsupported("/DT/NODA",
                            "nodal time step with another action (STOP, SET, KILL, the older CST1)",
                            "radx would need that action; it runs /DT/NODA (no action) and /DT/NODA/CST"));
    t.push_back(unsupported("/DT/INTER", "other interface time-step actions (SET, KILL, AMS, V4, V5)",
                            "radx would need that action; it runs /DT/INTER/CST, /DEL, /LAG and /STOP"));
    t.push_back(
        unsupported("/DT/BRICK", "brick time step with another action (none, DEL, KILL, SET)",
                    "radx would need that action on bricks; it runs /DT/BRICK/CST and /DT/BRICK/STOP"));
    t.push_back(
        unsupported("/DT/SHELL",
                    "4-node shell time step with another action (none or DEL: shells deleted below "
                    "Tmin; KILL, SET)",
                    "radx would need that action on shells; it runs /DT/SHELL/CST and /DT/SHELL/STOP"));
    {
      auto k = unsupported("/DT/SH_3N", "3-node shell time step with another action (none, DEL, KILL)",
                           "radx would need that action on 3-node shells; it runs /DT/SH_3N/CST and /STOP");
      k.aliases = {"/DT/SH3N"};
      t.push_back(std::move(k));
    }
    t.push_back(
        unsupported("/DT",
                    "other time-step controls (beams, springs, trusses, quads, airbags, SPH, ALE, "
                    "thermal, /DT/INTER/V5, /DT/SMSTR/V4, ...)",
                    "radx would need the time step of that element family or that action; it runs "
                    "/DT, /DT/NODA/CST, /DT/INTER/CST, /DEL, /LAG and /STOP, /DT/BRICK, /DT/SHELL and "
                    "/DT/SH_3N with /CST or /STOP, /DT/SPRING/STOP"));
    t.push_back(unsupported("/DT1", "the older per-family time-step options",
                            "radx would need them; write /DT/BRICK/CST or /DT/SHELL/CST instead"));
    {
      auto k = ekw("/DTIX", "first time step (at most DT_ini) and largest time step DT_max (0: no bound)");
      k.lines = {line({"DT_ini", "DT_max"}, 1, {dim::time, dim::time})};
      t.push_back(std::move(k));
    }
    t.push_back(unsupported("/DTSDE", "time step of degenerated bricks from their actual shape",
                            "radx would need the degenerated-brick time-step formula"));
    t.push_back(
        unsupported("/DT1TET10", "time step of 10-node tetrahedra", "radx would need 10-node tetrahedra"));
    t.push_back(unsupported("/DTTSH", "shell time step for thick shells", "radx would need thick shells"));
    t.push_back(unsupported("/DEL", "elements, parts or interfaces deleted at the start of the run",
                            "radx would need element and interface deletion from the engine deck"));
    t.push_back(unsupported("/DELINT", "deleted shells removed from TYPE7 interfaces (ON or OFF)",
                            "radx would need that switch; TYPE7's Idel of the starter deck does this"));
    t.push_back(
        unsupported("/VEL",
                    "an engine rigid link: the listed nodes share one velocity in the given directions "
                    "(/VEL/TRA|ROT), or an ALE grid-velocity link (/VEL/ALE)",
                    "radx would need engine-deck rigid links; /RBODY in the starter deck ties nodes "
                    "rigidly"));
    t.push_back(
        unsupported("/INIV", "velocities set again at the start of the run",
                    "radx would need engine-deck initial velocities; /INIVEL in the starter deck does "
                    "this"));
    t.push_back(unsupported("/BCS", "boundary conditions changed at the start of the run",
                            "radx would need engine-deck boundary conditions; /BCS in the starter deck does "
                            "this"));
    t.push_back(unsupported("/BCSR", "boundary conditions released at the start of the run",
                            "radx would need engine-deck boundary conditions"));
    t.push_back(unsupported(
        "/INTER", "interfaces changed at the start of the run (sort, start and stop times, FOP, TOP)",
        "radx would need engine-deck interface changes; Tstart and Tstop of the starter's "
        "/INTER do part of this"));
    t.push_back(unsupported("/FUNCT", "functions redefined for this run",
                            "radx would need engine-deck function updates"));
    t.push_back(unsupported("/IMPL", "implicit solution", "radx would need an implicit solver"));
    t.push_back(unsupported("/DYREL", "dynamic relaxation", "radx would need dynamic relaxation"));
    t.push_back(unsupported("/KEREL", "kinetic energy relaxation", "radx would need kinetic relaxation"));
    t.push_back(
        unsupported("/ADYREL", "adaptive dynamic relaxation", "radx would need adaptive dynamic relaxation"));
    t.push_back(unsupported("/DAMP", "Rayleigh damping changed at the start of the run",
                            "radx would need Rayleigh (mass and stiffness) damping"));
    t.push_back(unsupported("/NEGVOL", "action on a brick turned inside out (small strain, stop, delete)",
                            "radx would need those actions; it stops on an inverted element"));
    t.push_back(unsupported("/KILL", "stop without writing results on energy or mass error",
                            "radx would need that stop; /STOP gives the same criteria with results written"));
    t.push_back(unsupported("/STOP/LSENSOR", "stop when sensors switch",
                            "radx would need to stop a run when a sensor switches"));
    t.push_back(unsupported("/SENS", "sensors reset at the start of the run (/SENS/RESET)",
                            "radx would need runs that restart from earlier ones (its sensors start off)"));
    t.push_back(unsupported("/MASS", "mass added in earlier runs reset (/MASS/RESET)",
                            "radx would need runs that restart from earlier ones"));
    t.push_back(unsupported("/RERUN", "run that goes on from another run's restart file",
                            "radx would need restart files"));
    t.push_back(unsupported("/ALE", "ALE grid, solver and link options", "radx would need ALE"));
    t.push_back(unsupported("/ALESUB", "ALE sub-cycling (obsolete)", "radx would need ALE"));
    t.push_back(unsupported("/UPWM", "ALE momentum advection method", "radx would need ALE"));
    t.push_back(unsupported("/UPWIND", "ALE upwind coefficients", "radx would need ALE"));
    t.push_back(unsupported("/INCMP", "incompressible ALE flow (obsolete)", "radx would need ALE"));
    t.push_back(unsupported("/FLSEC", "flow sections (obsolete)", "radx would need ALE flow sections"));
    t.push_back(unsupported("/FVMBAG", "finite-volume airbag remeshing and changes",
                            "radx would need finite-volume airbags"));
    t.push_back(unsupported("/THERM", "thermal analysis options", "radx would need heat transfer"));
    t.push_back(unsupported("/MADYMO", "coupling with MADYMO", "radx would need that coupling"));
    t.push_back(
        unsupported("/RAD2RAD", "coupling with another Radioss run", "radx would need that coupling"));
    t.push_back(unsupported("/VIPER", "coupling with VIPER", "radx would need that coupling"));
    t.push_back(unsupported("/FXINP", "flexible bodies read from files", "radx would need flexible bodies"));
    t.push_back(unsupported("/EIG", "eigenproblems switched off", "radx would need flexible bodies"));
    t.push_back(ekw("/END/ENGINE", "end of the engine part of a one-file deck"));
    t.push_back(ekw("/END", "end of the engine deck"));
    return t;
  }();
  return table;
}

}  // namespace radx::schema
