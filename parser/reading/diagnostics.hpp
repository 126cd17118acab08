// Input diagnostics: every problem found in a deck is collected, coded and located, then reported
// together. Codes are stable: tests, scripts and users refer to them, so a code is never reused for
// another meaning. The codes are declared below (enum class Diag); what each one means is the table of
// code_table() in diagnostics.cpp, printed in docs/keywords.md ("Diagnostic codes").
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace radx {

enum class Severity : std::uint8_t { Note, Warning, Error };

// Stable diagnostic codes. Numbering: 1xx files and lines, 2xx fields, 3xx keywords and cards,
// 4xx ids and references, 5xx values, 6xx geometry and mesh, 7xx contact interfaces, 8xx engine deck, 9xx
// the model file as the engine reads it (io/hdf5/model_file_checks.hpp uses the same numbers).
enum class Diag : std::uint16_t {
  // files and lines
  FileNotFound = 101,
  IncludeLoop = 102,
  IncludeNotFound = 103,
  TabInFixedField = 104,
  MissingBegin = 105,
  MissingEnd = 106,
  NotUtf8OrBinary = 107,
  IncludedFileEnded = 108,
  IncludeForm = 109,
  // fields
  BadInteger = 201,
  BadReal = 202,
  RealOverflow = 203,
  IntegerOverflow = 204,
  FieldTruncated = 205,
  TextBeyondColumn100 = 206,
  TwoValuesInField = 207,
  // keywords and cards
  UnknownKeyword = 301,
  UnsupportedKeyword = 302,
  IgnoredControlCard = 303,
  MissingCard = 304,
  EmptyRecordList = 305,
  BadHeader = 306,
  UnsupportedVersion = 307,
  DuplicateSingleton = 308,
  MissingTitle = 309,
  ExtraData = 310,
  OutputNotWritten = 311,
  UnbalancedSubmodel = 312,
  // ids and references
  DuplicateId = 401,
  MissingReference = 402,
  EmptyGroup = 403,
  RequiredIdMissing = 404,
  UnusedNode = 405,
  ElementNodeMissing = 406,
  PartWrongKind = 407,
  // values
  ValueOutOfRange = 501,
  RequiredValueMissing = 502,
  BadPoisson = 503,
  NonPositiveThickness = 504,
  NonMonotonicFunction = 505,
  BadUnit = 506,
  InconsistentValues = 507,
  DefaultApplied = 508,
  UnimplementedOption = 509,
  PhysicsNotImplemented = 510,
  Substitution = 511,
  ImplausibleMaterial = 512,
  ImplausibleTimeStep = 513,
  // geometry
  NonPositiveVolume = 601,
  NonPositiveArea = 602,
  DegenerateElement = 603,
  RepeatedNodeInElement = 604,
  DegenerateTransform = 605,
  CoordinatesPerturbed = 606,
  TangledBrick = 607,
  RenumberedTetra = 608,
  // contact
  InitialPenetration = 701,
  InterfaceFieldIgnored = 702,
  BadFrictionLaw = 703,
  BadContactLaw = 704,
  TiedNodeWithoutSegment = 705,
  KinematicConflict = 706,
  // engine deck
  EngineMissingRun = 801,
  EngineBadLine = 802,
  EngineRunNameMismatch = 803,
  EngineNoEnd = 804,
  EngineRestartDecks = 805,
  DecompositionRanks = 806,
  BadGroupRankFile = 807,
  // model file
  ModelFileBadReference = 901,
  ModelFileBadValue = 902,
  ModelFileOtherFormat = 903,
  ModelFileChanged = 904,
  ModelFileOtherRun = 905,
};

// "RX" + number, e.g. RX402. Never changes once released.
std::string diag_code(Diag d);
// One-line summary of what the code means, for docs and --help.
std::string_view diag_summary(Diag d);
// All codes, in numeric order (for the generated reference).
const std::vector<Diag>& all_diag_codes();

struct Diagnostic {
  Severity severity = Severity::Error;
  Diag code = Diag::UnknownKeyword;
  std::string file;     // path as the user gave it (relative to the working folder)
  int line = 0;         // 1-based; 0 when the problem has no single line
  int column = 0;       // 1-based; 0 when unknown
  std::string keyword;  // e.g. "/INTER/TYPE7"
  std::int64_t id = 0;  // the object's user id, 0 when none
  std::string title;    // the object's title line, when it has one
  std::string message;  // what is wrong and what is accepted
};

// Where a diagnostic points: file, line and column in the deck.
struct Where {
  Where() = default;
  Where(std::string_view f, int l = 0, int c = 0) : file(f), line(l), column(c) {}
  std::string_view file;
  int line = 0;
  int column = 0;
};

// What object a diagnostic is about.
struct About {
  About() = default;
  About(std::string_view k, std::int64_t i = 0, std::string_view t = {}) : keyword(k), id(i), title(t) {}
  std::string_view keyword;
  std::int64_t id = 0;
  std::string_view title;
};

class Diagnostics {
 public:
  void add(Severity s, Diag code, Where where, About about, std::string message);
  void error(Diag code, Where where, About about, std::string message) {
    add(Severity::Error, code, where, about, std::move(message));
  }
  void warning(Diag code, Where where, About about, std::string message) {
    add(Severity::Warning, code, where, about, std::move(message));
  }
  void note(Diag code, Where where, About about, std::string message) {
    add(Severity::Note, code, where, about, std::move(message));
  }

  [[nodiscard]] bool has_errors() const { return errors_ > 0; }
  [[nodiscard]] std::size_t error_count() const { return errors_; }
  [[nodiscard]] std::size_t warning_count() const { return warnings_; }
  [[nodiscard]] const std::vector<Diagnostic>& items() const { return items_; }
  [[nodiscard]] bool contains(Diag code) const;

  // Sorted by file, line, column (stable), as editors expect them.
  void sort();
  // `file:line:col: error: RX402: [/PART/3 "title"] message` lines.
  void print(std::ostream& os) const;
  // The lines print() writes: one per diagnostic, except that one cause repeated (the same code, severity,
  // keyword and object id, and the same message once its numbers and quoted values are set aside) is shown
  // kRepeatsShown times, then counted in a closing "... and N more of the same" line. Counts are unchanged.
  [[nodiscard]] std::vector<std::string> lines() const;
  static constexpr std::size_t kRepeatsShown = 5;
  static std::string format(const Diagnostic& d);

 private:
  std::vector<Diagnostic> items_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
};

}  // namespace radx
