#include "parser/reading/diagnostics.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <ostream>
#include <sstream>

namespace radx {

namespace {

struct CodeInfo {
  Diag code;
  std::string_view summary;
};

// The one table of codes and what they mean; docs/keywords.md prints it.
const std::vector<CodeInfo>& code_table() {
  static const std::vector<CodeInfo> table = {
      {Diag::FileNotFound, "the deck file cannot be opened"},
      {Diag::IncludeLoop, "an #include chain includes a file that is already being read"},
      {Diag::IncludeNotFound, "an #include names a file that cannot be opened"},
      {Diag::TabInFixedField,
       "a tab character before a value in a fixed-column line: read as one blank column, as Radioss reads it "
       "(not as a jump to the next tab stop)"},
      {Diag::MissingBegin, "no /BEGIN line: the starter reads from /BEGIN to /END"},
      {Diag::MissingEnd, "no /END line: the file is truncated"},
      {Diag::NotUtf8OrBinary, "the file holds binary data (NUL bytes)"},
      {Diag::IncludedFileEnded,
       "an /END or #enddata line in an included file: it ends that file only, as Radioss reads it, and the "
       "deck goes on after the #include line"},
      {Diag::IncludeForm,
       "an #include read in a way worth knowing: a double-quoted name (OpenRadioss does not read it), or a "
       "file found beside the main deck rather than beside the including file (where Radioss looks next), or "
       "an "
       "empty file"},
      {Diag::BadInteger, "a field that must hold an integer holds something else"},
      {Diag::BadReal, "a field that must hold a real number holds something else"},
      {Diag::RealOverflow, "a real number outside the double-precision range"},
      {Diag::IntegerOverflow, "an integer outside the 64-bit range"},
      {Diag::FieldTruncated, "a number that does not fit its columns"},
      {Diag::TextBeyondColumn100, "text beyond column 100 is ignored"},
      {Diag::TwoValuesInField,
       "a number field holds two values (shifted columns): the leading one is read, as Radioss reads it"},
      {Diag::UnknownKeyword, "a keyword radx does not know"},
      {Diag::UnsupportedKeyword, "a Radioss keyword that radx does not support"},
      {Diag::IgnoredControlCard, "a control card accepted and ignored (it changes no physics)"},
      {Diag::MissingCard, "a card the keyword needs is missing"},
      {Diag::EmptyRecordList, "a keyword that lists records or ids has none"},
      {Diag::BadHeader, "the keyword line's id or unit id is not a positive integer"},
      {Diag::UnsupportedVersion,
       "the /BEGIN deck version is outside the versions radx reads, or a keyword is not read in that "
       "version"},
      {Diag::DuplicateSingleton, "a keyword that may appear once appears again"},
      {Diag::MissingTitle, "the keyword needs a title line"},
      {Diag::ExtraData, "data lines after the last card of a keyword"},
      {Diag::OutputNotWritten,
       "an output request for a file or field radx does not write (the run goes on without it)"},
      {Diag::UnbalancedSubmodel, "a //SUBMODEL without its //ENDSUB, or an //ENDSUB with no open //SUBMODEL"},
      {Diag::DuplicateId, "two objects of one kind share an id"},
      {Diag::MissingReference, "a reference to an object that does not exist"},
      {Diag::EmptyGroup, "a group or surface that holds nothing"},
      {Diag::RequiredIdMissing, "a required id field is blank or 0"},
      {Diag::UnusedNode, "a node used by no element"},
      {Diag::ElementNodeMissing, "an element refers to a node that does not exist"},
      {Diag::PartWrongKind, "a part of the wrong kind for this use (solid part in /SURF/PART, ...)"},
      {Diag::ValueOutOfRange, "a value outside the accepted set or range"},
      {Diag::RequiredValueMissing, "a value the keyword needs is blank or 0"},
      {Diag::BadPoisson, "Poisson's ratio outside [0, 0.5)"},
      {Diag::NonPositiveThickness,
       "a shell thickness that is negative, or zero on both element and property"},
      {Diag::NonMonotonicFunction, "function abscissas that are not strictly increasing"},
      {Diag::BadUnit, "a unit name or factor that radx does not know"},
      {Diag::InconsistentValues, "values that contradict each other"},
      {Diag::DefaultApplied, "a value replaced by a default worth knowing about"},
      {Diag::UnimplementedOption,
       "an option radx reads but does not implement: a warning where it changes no result (it is left "
       "out), an error where it would (the deck is refused, naming the option)"},
      {Diag::PhysicsNotImplemented,
       "a formulation, option or value that changes the physics and that radx does not implement "
       "(--allow-substitutions runs the nearest one radx implements instead)"},
      {Diag::Substitution,
       "--allow-substitutions: a formulation or option replaced by the nearest one radx implements"},
      {Diag::ImplausibleMaterial,
       "a material whose wave speed is implausible: above the speed of light or below 1 m/s"},
      {Diag::ImplausibleTimeStep,
       "an implausible initial time step (below 1e-12 s) or end time (more than 1e9 cycles)"},
      {Diag::NonPositiveVolume, "a solid element with zero or negative volume"},
      {Diag::NonPositiveArea, "a shell element with zero area"},
      {Diag::DegenerateElement, "a degenerate element (repeated nodes) used as a lower-order shape"},
      {Diag::RepeatedNodeInElement, "an element lists the same node where that is not allowed"},
      {Diag::DegenerateTransform,
       "a /TRANSFORM whose axis or plane normal has zero length (two points or nodes at one place)"},
      {Diag::CoordinatesPerturbed, "node coordinates moved by a random perturbation (/RANDOM)"},
      {Diag::TangledBrick,
       "a brick with positive volume but a corner turned inside out (a negative corner Jacobian: faces that "
       "intersect, or a re-entrant corner)"},
      {Diag::RenumberedTetra,
       "a tetrahedron given with negative volume; the starter swaps n2 and n4, as Radioss does"},
      {Diag::InitialPenetration, "secondary nodes closer to the main surface than the gap at t = 0"},
      {Diag::InterfaceFieldIgnored, "an interface field radx reads but does not use is set"},
      {Diag::BadFrictionLaw, "friction law coefficients that are inconsistent"},
      {Diag::BadContactLaw,
       "a /CTCLAW law string that cannot be read, or a law parameter that is unknown, missing, repeated, out "
       "of range or inconsistent (the curve of a tabulated law included)"},
      {Diag::TiedNodeWithoutSegment,
       "/INTER/TYPE2 secondary nodes that find no main segment within the search distance"},
      {Diag::KinematicConflict,
       "a node under two kinematic conditions that cannot both hold (a tied node also tied elsewhere, in a "
       "rigid body or under /BCS)"},
      {Diag::EngineMissingRun, "the engine deck has no /RUN"},
      {Diag::EngineBadLine, "an engine deck data line with too few or unreadable values"},
      {Diag::EngineRunNameMismatch, "the /RUN name or number differs from the file name"},
      {Diag::EngineNoEnd,
       "the engine deck has no /END line: it is read to the end of the file, as Radioss does"},
      {Diag::EngineRestartDecks,
       "NAME_0002.rad and later beside the engine deck: OpenRadioss restart decks, which radx does not run"},
      {Diag::DecompositionRanks,
       "radx-engine --decompose P: more ranks than the model has element groups to deal out (after each "
       "small "
       "rigid body's groups are joined)"},
      {Diag::BadGroupRankFile,
       "a group-rank file (radx-engine --partition) line that is not \"GROUP RANK\" with both in range, a "
       "group given twice, a group given no rank, or a rank given no group (a file for another rank count)"},
      {Diag::ModelFileBadReference,
       "a model-file entry the engine cannot use: an index out of range, arrays of different lengths, a "
       "repeated "
       "id, an unknown code, a skew or sensor id the model lacks"},
      {Diag::ModelFileBadValue,
       "a model-file value the physics cannot take: not finite, a negative mass, density, modulus or "
       "thickness, "
       "every nodal mass 0"},
      {Diag::ModelFileOtherFormat, "the model file is of another format version: written by another radx"},
      {Diag::ModelFileChanged,
       "the model file was changed after the starter wrote it (its content hash differs), or has no content "
       "hash"},
      {Diag::ModelFileOtherRun,
       "the model file is the model of another run: the starter wrote it for another deck than the engine "
       "deck's"},
  };
  return table;
}

}  // namespace

std::string diag_code(Diag d) {
  return "RX" + std::to_string(static_cast<int>(d));
}

std::string_view diag_summary(Diag d) {
  for (const auto& c : code_table())
    if (c.code == d) return c.summary;
  return "";
}

const std::vector<Diag>& all_diag_codes() {
  static const std::vector<Diag> codes = [] {
    std::vector<Diag> v;
    for (const auto& c : code_table()) v.push_back(c.code);
    return v;
  }();
  return codes;
}

void Diagnostics::add(Severity s, Diag code, Where where, About about, std::string message) {
  Diagnostic d;
  d.severity = s;
  d.code = code;
  d.file = std::string(where.file);
  d.line = where.line;
  d.column = where.column;
  d.keyword = std::string(about.keyword);
  d.id = about.id;
  d.title = std::string(about.title);
  d.message = std::move(message);
  if (s == Severity::Error) ++errors_;
  if (s == Severity::Warning) ++warnings_;
  items_.push_back(std::move(d));
}

bool Diagnostics::contains(Diag code) const {
  return std::any_of(items_.begin(), items_.end(), [&](const Diagnostic& d) { return d.code == code; });
}

void Diagnostics::sort() {
  std::stable_sort(items_.begin(), items_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.file != b.file) return a.file < b.file;
    if (a.line != b.line) return a.line < b.line;
    return a.column < b.column;
  });
}

std::string Diagnostics::format(const Diagnostic& d) {
  std::ostringstream os;
  os << (d.file.empty() ? std::string("radx") : d.file);
  if (d.line > 0) os << ':' << d.line;
  if (d.line > 0 && d.column > 0) os << ':' << d.column;
  os << ": ";
  switch (d.severity) {
    case Severity::Error: os << "error"; break;
    case Severity::Warning: os << "warning"; break;
    case Severity::Note: os << "note"; break;
  }
  os << ": " << diag_code(d.code) << ": ";
  if (!d.keyword.empty()) {
    os << '[' << d.keyword;
    if (d.id != 0) os << " id " << d.id;
    if (!d.title.empty()) os << " \"" << d.title << '"';
    os << "] ";
  }
  os << d.message;
  return os.str();
}

namespace {

// What makes two diagnostics one cause: code, severity, keyword and object id, and the message with its
// numbers and quoted values masked (nodes 12 and 13 missing from one group are one cause; a missing group and
// a missing material are two, and so are the same warning on two interfaces).
std::string cause_of(const Diagnostic& d) {
  std::string key = diag_code(d.code) + static_cast<char>('0' + static_cast<int>(d.severity)) + d.keyword +
                    '#' + std::to_string(d.id) + '|';
  bool in_quote = false;
  bool in_number = false;
  for (const char c : d.message) {
    if (c == '\'') {
      in_quote = !in_quote;
      key += '\'';
      continue;
    }
    if (in_quote) continue;
    const bool digit = std::isdigit(static_cast<unsigned char>(c)) != 0;
    if (digit && !in_number) key += '#';
    in_number = digit || (in_number && (c == '.' || c == 'e' || c == 'E' || c == '-' || c == '+'));
    if (!in_number) key += c;
  }
  return key;
}

}  // namespace

std::vector<std::string> Diagnostics::lines() const {
  std::vector<std::string> out;
  struct Cause {
    std::size_t count = 0;
    const Diagnostic* first = nullptr;
  };
  std::map<std::string, Cause> causes;
  std::vector<const Cause*> capped;
  for (const auto& d : items_) {
    Cause& c = causes[cause_of(d)];
    if (c.count++ == 0) c.first = &d;
    if (c.count <= kRepeatsShown) out.push_back(format(d));
    if (c.count == kRepeatsShown + 1) capped.push_back(&c);
  }
  for (const Cause* c : capped) {
    const Diagnostic& d = *c->first;
    std::string kind = d.severity == Severity::Error     ? "error"
                       : d.severity == Severity::Warning ? "warning"
                                                         : "note";
    // Not in the `file:line: error: RXnnn:` shape: it stands for diagnostics, it is not one.
    out.push_back("radx: ... and " + std::to_string(c->count - kRepeatsShown) + " more of the same (" +
                  diag_code(d.code) + " " + kind + "s like the one at " +
                  (d.file.empty() ? std::string("radx") : d.file) + ":" + std::to_string(d.line) +
                  ", not shown; " + std::to_string(c->count) + " in all)");
  }
  return out;
}

void Diagnostics::print(std::ostream& os) const {
  for (const auto& l : lines()) os << l << '\n';
}

}  // namespace radx
