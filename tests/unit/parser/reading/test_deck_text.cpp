// The text layer of the reader: comments, includes, CRLF, trailing blanks, free format, tabs.
#include <catch2/catch.hpp>

#include "parser/reading/deck.hpp"
#include "solver/model/run_files.hpp"
#include "test_util.hpp"

using radx::Diag;
using radx::test::Line;
using radx::test::TempDir;

namespace {

std::string node_line(long long id, double x, double y, double z) {
  return Line().put(id, 1, 10).put(x, 11, 30).put(y, 31, 50).put(z, 51, 70).str();
}

std::string codes(const radx::Diagnostics& d) {
  std::string s;
  for (const auto& i : d.items()) s += radx::Diagnostics::format(i) + "\n";
  return s;
}

}  // namespace

TEST_CASE("comments between cards, CRLF and trailing blanks do not change values", "[lexer]") {
  TempDir dir;
  std::string deck = radx::test::begin_block(2026);
  deck += "/NODE\n# a comment line\r\n$ another comment\r\n" + node_line(1, 1.5, 2.5, 3.5) + "   \r\n" +
          "#---1----|----2----|\r\n" + node_line(2, -1, 0, 1e3) + "\r\n/END\r\n";
  for (auto& c : deck)
    if (c == '\n') c = '\n';
  const auto path = dir.write("crlf_0000.rad", deck);
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  const auto nodes = d.of("/NODE");
  REQUIRE(nodes.size() == 1);
  const auto& t = nodes[0]->records;
  REQUIRE(t.size() == 2);
  CHECK(t.ints[t.column("node_ID")][1] == 2);
  CHECK(t.reals[t.column("X")][0] == 1.5);
  CHECK(t.reals[t.column("Z")][1] == 1000.0);
  // Positions point at the physical lines of the file (comments counted).
  CHECK(t.pos[0].line == 9);
  CHECK(t.pos[1].line == 11);
}

TEST_CASE("#include inserts a file relative to the including file", "[lexer]") {
  TempDir dir;
  dir.write("sub/nodes.inc", node_line(7, 1, 2, 3) + "\n");
  const auto path =
      dir.write("inc_0000.rad", radx::test::begin_block(2026) + "/NODE\n#include sub/nodes.inc\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  const auto& t = d.of("/NODE")[0]->records;
  REQUIRE(t.size() == 1);
  CHECK(t.ints[t.column("node_ID")][0] == 7);
  CHECK(d.files[t.pos[0].file].find("nodes.inc") != std::string::npos);
  CHECK(t.pos[0].line == 1);
}

TEST_CASE("an include loop and a missing include are located errors", "[lexer]") {
  TempDir dir;
  dir.write("a.inc", "#include b.inc\n");
  dir.write("b.inc", "\n#include a.inc\n");
  const auto path = dir.write("loop_0000.rad",
                              radx::test::begin_block(2026) + "#include a.inc\n#include missing.inc\n/END\n");
  radx::Diagnostics diags;
  radx::read_starter_deck(path, diags);
  REQUIRE(diags.contains(Diag::IncludeLoop));
  REQUIRE(diags.contains(Diag::IncludeNotFound));
  for (const auto& i : diags.items()) {
    if (i.code == Diag::IncludeLoop) {
      CHECK(i.file.find("b.inc") != std::string::npos);
      CHECK(i.line == 2);
    }
    if (i.code == Diag::IncludeNotFound) CHECK(i.line == 7);
  }
}

TEST_CASE("a file whose reported size is 0 is read to its end, and an empty include is said", "[lexer]") {
  TempDir dir;
  // /proc/self/environ reports size 0 and holds the environment, NUL-separated: read whole, it is refused as
  // binary, where a read of the reported size took it for an empty file without a word.
  const auto proc =
      dir.write("proc_0000.rad", radx::test::begin_block(2026) + "#include /proc/self/environ\n/END\n");
  radx::Diagnostics d1;
  radx::read_starter_deck(proc, d1);
  INFO(codes(d1));
  CHECK(d1.contains(Diag::NotUtf8OrBinary));
  // An absolute name that cannot be opened gets no hint about relative names.
  const auto absent = dir.write(
      "abs_0000.rad", radx::test::begin_block(2026) + "#include /nonexistent/radx/nodes.inc\n/END\n");
  radx::Diagnostics d2;
  radx::read_starter_deck(absent, d2);
  REQUIRE(d2.contains(Diag::IncludeNotFound));
  for (const auto& i : d2.items())
    if (i.code == Diag::IncludeNotFound) CHECK(i.message.find("relative") == std::string::npos);
  // A relative one does, naming where it was looked for.
  const auto rel = dir.write("rel_0000.rad", radx::test::begin_block(2026) + "#include sub/none.inc\n/END\n");
  radx::Diagnostics d3;
  radx::read_starter_deck(rel, d3);
  REQUIRE(d3.contains(Diag::IncludeNotFound));
  for (const auto& i : d3.items())
    if (i.code == Diag::IncludeNotFound)
      CHECK(i.message.find("beside the including file") != std::string::npos);
  // An empty included file is read as nothing, with a warning at its #include line.
  dir.write("empty.inc", "");
  const auto empty =
      dir.write("empty_0000.rad", radx::test::begin_block(2026) + "/NODE\n#include empty.inc\n/END\n");
  radx::Diagnostics d4;
  radx::read_starter_deck(empty, d4);
  INFO(codes(d4));
  REQUIRE(d4.contains(Diag::IncludeForm));
  for (const auto& i : d4.items())
    if (i.code == Diag::IncludeForm) {
      CHECK(i.severity == radx::Severity::Warning);
      CHECK(i.message.find("empty") != std::string::npos);
      CHECK(i.line == 7);
    }
}

TEST_CASE("a comma line is read as free format, field by field in declaration order", "[lexer]") {
  TempDir dir;
  const auto path =
      dir.write("free_0000.rad", radx::test::begin_block(2026) + "/NODE\n 3, 1.D3, .5 ,-2\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  const auto& t = d.of("/NODE")[0]->records;
  CHECK(t.ints[t.column("node_ID")][0] == 3);
  CHECK(t.reals[t.column("X")][0] == 1000.0);
  CHECK(t.reals[t.column("Y")][0] == 0.5);
  CHECK(t.reals[t.column("Z")][0] == -2.0);
}

TEST_CASE("a tab in a fixed-column line is one blank column, as Radioss reads it, with a warning",
          "[lexer]") {
  TempDir dir;
  // Node 1: the tab is column 11, so X = 1.0 sits in columns 12-14 of its field 11-30; the comma line's tab
  // is a blank.
  const auto path = dir.write("tab_0000.rad",
                              radx::test::begin_block(2026) + "/NODE\n         1\t1.0\n2,\t3.,4.,5.\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  REQUIRE(diags.warning_count() == 1);
  const auto& e = diags.items().front();
  CHECK(e.code == Diag::TabInFixedField);
  CHECK(e.severity == radx::Severity::Warning);
  CHECK(e.line == 7);
  CHECK(e.column == 11);
  CHECK(e.message.find("one blank column") != std::string::npos);
  const auto& t = d.of("/NODE")[0]->records;
  REQUIRE(t.size() == 2);
  CHECK(t.reals[t.column("X")][0] == 1.0);
  CHECK(t.reals[t.column("X")][1] == 3.0);
}

TEST_CASE("an id-list cell of several tab-separated ids is refused, naming what Radioss would drop",
          "[lexer]") {
  TempDir dir;
  // "1<tab>2<tab>3" fills one 10-column cell: Radioss reads id 1 only. A tab before one id in its cell is
  // read.
  const auto path = dir.write("tabids_0000.rad", radx::test::begin_block(2026) +
                                                     "/GRNOD/NODE/7\ntabs\n1\t2\t3\n         4\t5\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE(diags.error_count() == 1);
  for (const auto& i : diags.items())
    if (i.severity == radx::Severity::Error) {
      CHECK(i.code == Diag::BadInteger);
      CHECK(i.line == 8);
      CHECK(i.message.find("Radioss reads only the first (1) and drops 2, 3") != std::string::npos);
    }
  const auto g = d.of("/GRNOD/NODE");
  REQUIRE(g.size() == 1);
  CHECK(g[0]->ids == std::vector<std::int64_t>{4, 5});
}

TEST_CASE("#INCLUDE and #Include are include lines, and a single-quoted name is read", "[lexer]") {
  TempDir dir;
  dir.write("a.inc", node_line(7, 1, 2, 3) + "\n");
  dir.write("b.inc", node_line(8, 1, 2, 3) + "\n");
  const auto path = dir.write(
      "upper_0000.rad", radx::test::begin_block(2026) + "/NODE\n#INCLUDE a.inc\n#Include 'b.inc'\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  CHECK(diags.warning_count() == 0);
  CHECK(d.of("/NODE")[0]->records.size() == 2);
}

TEST_CASE("a double-quoted include name is read with a warning that OpenRadioss does not read it",
          "[lexer]") {
  TempDir dir;
  dir.write("a.inc", node_line(7, 1, 2, 3) + "\n");
  const auto path =
      dir.write("dq_0000.rad", radx::test::begin_block(2026) + "/NODE\n#include \"a.inc\"\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  REQUIRE(diags.contains(Diag::IncludeForm));
  CHECK(d.of("/NODE")[0]->records.size() == 1);
}

TEST_CASE("/END in an included file ends that file only, and the deck goes on after the #include",
          "[lexer]") {
  TempDir dir;
  dir.write("a.inc", node_line(7, 1, 2, 3) + "\n/END\n/FOOBAR/1\n");
  dir.write("b.inc", node_line(9, 1, 2, 3) + "\n#enddata\n" + node_line(10, 0, 0, 0) + "\n");
  const auto path = dir.write("endinc_0000.rad", radx::test::begin_block(2026) + "/NODE\n#include a.inc\n" +
                                                     node_line(8, 1, 2, 3) + "\n#include b.inc\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  const auto& t = d.of("/NODE")[0]->records;
  REQUIRE(t.size() == 3);
  CHECK(t.ints[t.column("node_ID")][0] == 7);
  CHECK(t.ints[t.column("node_ID")][1] == 8);
  CHECK(t.ints[t.column("node_ID")][2] == 9);
  int warnings = 0;
  for (const auto& i : diags.items())
    if (i.code == Diag::IncludedFileEnded && i.severity == radx::Severity::Warning) {
      ++warnings;
      CHECK(i.line == 2);
    }
  CHECK(warnings == 2);
}

TEST_CASE("a main file that only includes the model ends at the included /END", "[lexer]") {
  TempDir dir;
  dir.write("model.inc", radx::test::begin_block(2026) + "/NODE\n" + node_line(7, 1, 2, 3) + "\n/END\n");
  const auto path = dir.write("wrap_0000.rad", "#include model.inc\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  CHECK(d.of("/NODE")[0]->records.size() == 1);
}

TEST_CASE("an include not beside its including file is looked for beside the main deck, as Radioss does",
          "[lexer]") {
  TempDir dir;
  dir.write("sub/a.inc", "#include b.inc\n");
  dir.write("b.inc", node_line(7, 1, 2, 3) + "\n");
  const auto path =
      dir.write("main_0000.rad", radx::test::begin_block(2026) + "/NODE\n#include sub/a.inc\n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  CHECK(diags.contains(Diag::IncludeForm));
  CHECK(d.of("/NODE")[0]->records.size() == 1);
}

TEST_CASE("tabs among the trailing blanks of a fixed-column line move no value and are accepted", "[lexer]") {
  TempDir dir;
  // Node 1's line ends with blanks and a tab after its last value; an otherwise blank card holds a tab.
  const auto path = dir.write("tab_0000.rad", radx::test::begin_block(2026) + "/NODE\n" +
                                                  node_line(1, 1.5, 2.5, 3.5) + "   \t  \n/END\n");
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  const auto& t = d.of("/NODE")[0]->records;
  REQUIRE(t.size() == 1);
  CHECK(t.reals[t.column("Z")][0] == 3.5);
}

TEST_CASE("letters in a number, an overflowing real and text past column 100 are reported", "[lexer]") {
  TempDir dir;
  std::string bad = node_line(1, 0, 0, 0);
  bad.replace(25, 5, "1.0x5");
  std::string overflow = Line().put(2LL, 1, 10).put("1e400", 11, 30).str();
  std::string wide = node_line(3, 0, 0, 0);
  wide.resize(100, ' ');
  wide += "junk";
  const auto path = dir.write("bad_0000.rad", radx::test::begin_block(2026) + "/NODE\n" + bad + "\n" +
                                                  overflow + "\n" + wide + "\n/END\n");
  radx::Diagnostics diags;
  radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  REQUIRE(diags.contains(Diag::BadReal));
  REQUIRE(diags.contains(Diag::RealOverflow));
  REQUIRE(diags.contains(Diag::TextBeyondColumn100));
  for (const auto& i : diags.items()) {
    if (i.code == Diag::BadReal) CHECK((i.line == 7 && i.column == 11));
    if (i.code == Diag::RealOverflow) CHECK(i.line == 8);
    if (i.code == Diag::TextBeyondColumn100) CHECK((i.line == 9 && i.column == 101));
  }
}

TEST_CASE("a one-file deck splits at /END/ENGINE for both readers", "[lexer]") {
  TempDir dir;
  const std::string text = "/RUN/ONE/1\n0.01\n/PRINT/-10\n/END/ENGINE\n" + radx::test::begin_block(2019) +
                           "/NODE\n" + node_line(1, 0, 0, 0) + "\n/END\n";
  const auto path = dir.write("ONE.rad", text);
  CHECK(radx::model::is_one_file_deck(path));
  radx::Diagnostics diags;
  const auto s = radx::read_starter_deck(path, diags);
  const auto e = radx::read_engine_deck(path, diags);
  INFO(codes(diags));
  REQUIRE_FALSE(diags.has_errors());
  CHECK(s.version == 2019);
  CHECK(s.of("/NODE").size() == 1);
  REQUIRE(e.of("/RUN").size() == 1);
  CHECK(e.of("/RUN")[0]->value(0, 0) == 0.01);
  CHECK(e.of("/PRINT").size() == 1);
}

TEST_CASE("/BEGIN/0 and /BEGIN/ are read as /BEGIN with a note, /BEGIN/X is not /BEGIN", "[lexer]") {
  // Older generators write a field after /BEGIN; Radioss finds /BEGIN by its prefix and reads the deck.
  for (const std::string head : {"/BEGIN/0", "/BEGIN/"}) {
    INFO(head);
    TempDir dir;
    std::string deck = radx::test::begin_block(2026);
    deck.replace(0, 6, head);
    deck += "/NODE\n" + node_line(1, 1.5, 2.5, 3.5) + "\n/END\n";
    radx::Diagnostics diags;
    const auto d = radx::read_starter_deck(dir.write("b_0000.rad", deck), diags);
    INFO(codes(diags));
    REQUIRE_FALSE(diags.has_errors());
    CHECK(d.version == 2026);
    REQUIRE(d.of("/NODE").size() == 1u);
    if (head == "/BEGIN/0")
      CHECK(codes(diags).find("the field after /BEGIN is ignored") != std::string::npos);
  }
  TempDir dir;
  std::string deck = radx::test::begin_block(2026);
  deck.replace(0, 6, "/BEGIN/X");
  radx::Diagnostics diags;
  (void)radx::read_starter_deck(dir.write("x_0000.rad", deck + "/END\n"), diags);
  CHECK(codes(diags).find("RX105") != std::string::npos);  // no /BEGIN: a word after it is another keyword
}

TEST_CASE(
    "a material, property or time history radx lacks is a Radioss keyword not supported, with the ones radx "
    "reads",
    "[lexer]") {
  TempDir dir;
  const auto path =
      dir.write("fam_0000.rad", radx::test::begin_block(2026) +
                                    "/MAT/LAW51/3\nmultimaterial\n/TH/QUAD/1\nquads\n/FOOBAR/1\n/END\n");
  radx::Diagnostics diags;
  (void)radx::read_starter_deck(path, diags);
  const std::string all = codes(diags);
  INFO(all);
  // Line 6 and 8: RX302 (not "unknown, check the spelling"), naming what radx reads in that family.
  CHECK(all.find("6:1: error: RX302: [/MAT/LAW51 id 3] /MAT/LAW51 is not a material law radx reads") !=
        std::string::npos);
  CHECK(all.find("radx reads /MAT/LAW1, /MAT/ELAST") != std::string::npos);
  CHECK(all.find("8:1: error: RX302: [/TH/QUAD id 1]") != std::string::npos);
  CHECK(all.find("/TH/NODE") != std::string::npos);
  // A word outside every Radioss family stays unknown.
  CHECK(all.find("10:1: error: RX301: [/FOOBAR]") != std::string::npos);
}

TEST_CASE("a reference to a keyword radx does not read names that keyword, not a missing id", "[lexer]") {
  // /PART 1 takes /PROP/SPR_PRE 11 (line 9), which radx refuses (RX302): the part's RX402 must say that
  // prop_ID 11 is that keyword, with its line; a reference to an id no keyword has keeps "there is no".
  TempDir dir;
  const std::string deck = radx::test::begin_block(2026) + "/NODE\n" + node_line(1, 0, 0, 0) + "\n" +
                           node_line(2, 1, 0, 0) + "\n/PROP/SPR_PRE/11\npretensioner\n" +
                           "/PART/1\npart one\n" + Line().put(11, 1, 10).put(1, 11, 20).str() + "\n" +
                           "/PART/2\npart two\n" + Line().put(12, 1, 10).put(1, 11, 20).str() + "\n" +
                           "/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
                           Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n/END\n";
  const auto path = dir.write("unread_0000.rad", deck);
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  (void)radx::build_model(d, diags);
  const std::string all = codes(diags);
  INFO(all);
  CHECK(all.find("RX302: [/PROP/SPR_PRE id 11]") != std::string::npos);
  CHECK(all.find("prop_ID = 11 names /PROP/SPR_PRE 11 (" + path + ":9)") != std::string::npos);
  CHECK(all.find("prop_ID = 12: there is no /PROP/12 in the deck") != std::string::npos);
}

TEST_CASE("a card field holding two numbers reads the leading one with a warning, as Radioss does",
          "[lexer]") {
  // /MAT/LAW1 1's E field (columns 1-20) holds "210000.0      5.0" (a card whose columns slid): Radioss's
  // sscanf reads 210000; radx too, with RX207. Material 2's E field "1.5 E-3" is not two numbers (a blank
  // inside one): an error, as before. A /NODE record whose X cell holds two numbers is an error too: record
  // lines written without columns are not read by their leading values.
  TempDir dir;
  std::string node = node_line(1, 0, 0, 0);
  node.replace(10, 20, "       1.5       2.5");
  const std::string deck = radx::test::begin_block(2026) + "/NODE\n" + node + "\n/MAT/LAW1/1\nshifted\n" +
                           Line().put(7.85e-9, 1, 20).str() + "\n" + "  210000.0      5.0" +
                           Line().put(0.3, 21, 40).str().substr(19) + "\n/MAT/LAW1/2\nblank in exponent\n" +
                           Line().put(7.85e-9, 1, 20).str() + "\n" + "             1.5 E-3" +
                           Line().put(0.3, 21, 40).str().substr(20) + "\n/END\n";
  const auto path = dir.write("two_0000.rad", deck);
  radx::Diagnostics diags;
  const auto d = radx::read_starter_deck(path, diags);
  INFO(codes(diags));
  const auto mats = d.of("/MAT/LAW1");
  REQUIRE(mats.size() == 2u);
  CHECK(mats[0]->get_real("E") == 210000.0);  // the leading value, exactly
  CHECK(mats[0]->get_real("nu") == 0.3);
  int two = 0, bad = 0;
  for (const auto& i : diags.items()) {
    if (i.code == Diag::TwoValuesInField) {
      ++two;
      CHECK((i.line == 11 && i.column == 1));
    }
    if (i.code == Diag::BadReal) {
      ++bad;
      CHECK((i.line == 7 || i.line == 15));  // the /NODE cell and law 2's E
    }
  }
  CHECK(two == 1);
  CHECK(bad == 2);
}
