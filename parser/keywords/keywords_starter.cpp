// The starter deck's keywords as data: one declaration per keyword of the subset radx reads (see
// docs/theory/deck-format.md section 2, docs/theory/type7-lagdt.md section 3 and docs/theory/contact-laws.md
// section 5), in the order docs/keywords.md lists them (it is generated from these declarations), plus the
// list of real Radioss keywords radx knows but does not support.
//
// Conventions used throughout:
// * Version bands follow the FORMAT(radiossNNN) blocks OpenRadioss reads a deck with: for each keyword, the
//   block with the highest NNN at or below the deck's version (INVERS) in the keyword's newest reader file,
//   or the lowest block above it when there is none (SHELL, SH3N, BRICK, BOX/RECTA and RANDOM have only a
//   110 block, which Radioss also applies to 90 and 100 decks). A band's first version is the first deck
//   version radx reads (schema::kDeckVersions) that has the layout; the earliest band starts at kAnyVersion.
//   Old bands are given as versions(kAnyVersion, 130) and so on: 130 is the last format before 140.
// * zero_is() only for constant defaults; defaults that depend on other fields or on /DEF_SHELL and
//   /DEF_SOLID are resolved by the model builder from the raw value.
// * unused(): read and echoed, but radx does not act on it; a non-default value warns.
#include <array>
#include <string>
#include <tuple>
#include <vector>

#include "parser/keywords/keyword_schema.hpp"

namespace radx::schema {

namespace {

CardDecl card(std::string_view name, std::vector<FieldDecl> fields) {
  CardDecl c;
  c.name = name;
  c.fields = std::move(fields);
  return c;
}

CardDecl card_if(std::string_view name, Condition cond, std::vector<FieldDecl> fields) {
  CardDecl c = card(name, std::move(fields));
  c.condition = cond;
  return c;
}

CardDecl card_v(std::string_view name, int since, int until, std::vector<FieldDecl> fields) {
  CardDecl c = card(name, std::move(fields));
  c.since = since;
  c.until = until;
  return c;
}

// A card of some versions only, read when its condition holds.
CardDecl card_v_if(std::string_view name, int since, int until, Condition cond,
                   std::vector<FieldDecl> fields) {
  CardDecl c = card_v(name, since, until, std::move(fields));
  c.condition = cond;
  return c;
}

// Multimp, the memory-sizing field of the old TYPE7 layouts (Radioss reads it only for TYPE19).
FieldDecl multimp() {
  return I("Multimp", 51, 60, "impacted segments per node, memory sizing of old layouts").unused();
}

KeywordDecl kw(std::string_view path, std::string_view meaning, Header header, bool has_title,
               std::string_view id_name = "id") {
  KeywordDecl k;
  k.path = path;
  k.meaning = meaning;
  k.header = header;
  k.has_title = has_title;
  k.id_name = id_name;
  // The keyword line's id: a material, a property, a part (an element block names its part), else an
  // object of the default offset.
  const auto starts = [&](std::string_view p) { return path.substr(0, p.size()) == p; };
  if (starts("/MAT/")) k.id_kind = IdKind::Material;
  if (starts("/PROP/")) k.id_kind = IdKind::Property;
  if (path == "/PART" || header == Header::PartId) k.id_kind = IdKind::Part;
  return k;
}

// The three cards of each of the six laws of /PROP/SPR_GENE (TYPE8) and /PROP/SPR_BEAM (TYPE13), one block
// per degree of freedom (1..3 translations X Y Z, 4..6 rotations), with the fields of /PROP/SPRING numbered
// by degree of freedom as the Radioss manual numbers them; `blocks` names the cards [dof][card].
using SixBlockNames = std::array<std::array<std::string_view, 3>, 6>;
constexpr SixBlockNames kSprGeneBlocks = {{
    {"X translation: card 1", "X translation: card 2", "X translation: card 3"},
    {"Y translation: card 1", "Y translation: card 2", "Y translation: card 3"},
    {"Z translation: card 1", "Z translation: card 2", "Z translation: card 3"},
    {"X rotation: card 1", "X rotation: card 2", "X rotation: card 3"},
    {"Y rotation: card 1", "Y rotation: card 2", "Y rotation: card 3"},
    {"Z rotation: card 1", "Z rotation: card 2", "Z rotation: card 3"},
}};
constexpr SixBlockNames kSprBeamBlocks = {{
    {"X tension: card 1", "X tension: card 2", "X tension: card 3"},
    {"Y shear: card 1", "Y shear: card 2", "Y shear: card 3"},
    {"Z shear: card 1", "Z shear: card 2", "Z shear: card 3"},
    {"X torsion: card 1", "X torsion: card 2", "X torsion: card 3"},
    {"Y bending: card 1", "Y bending: card 2", "Y bending: card 3"},
    {"Z bending: card 1", "Z bending: card 2", "Z bending: card 3"},
}};

void add_six_spring_laws(KeywordDecl& k, const SixBlockNames& blocks) {
  // Field names of the six blocks: [field][dof].
  static constexpr std::array<std::array<std::string_view, 6>, 16> n = {{
      {"K1", "K2", "K3", "K4", "K5", "K6"},
      {"C1", "C2", "C3", "C4", "C5", "C6"},
      {"A1", "A2", "A3", "A4", "A5", "A6"},
      {"B1", "B2", "B3", "B4", "B5", "B6"},
      {"D1", "D2", "D3", "D4", "D5", "D6"},
      {"fct_ID11", "fct_ID12", "fct_ID13", "fct_ID14", "fct_ID15", "fct_ID16"},
      {"H1", "H2", "H3", "H4", "H5", "H6"},
      {"fct_ID21", "fct_ID22", "fct_ID23", "fct_ID24", "fct_ID25", "fct_ID26"},
      {"fct_ID31", "fct_ID32", "fct_ID33", "fct_ID34", "fct_ID35", "fct_ID36"},
      {"fct_ID41", "fct_ID42", "fct_ID43", "fct_ID44", "fct_ID45", "fct_ID46"},
      {"delta_min1", "delta_min2", "delta_min3", "delta_min4", "delta_min5", "delta_min6"},
      {"delta_max1", "delta_max2", "delta_max3", "delta_max4", "delta_max5", "delta_max6"},
      {"F1", "F2", "F3", "F4", "F5", "F6"},
      {"E1", "E2", "E3", "E4", "E5", "E6"},
      {"Ascale1", "Ascale2", "Ascale3", "Ascale4", "Ascale5", "Ascale6"},
      {"Hscale1", "Hscale2", "Hscale3", "Hscale4", "Hscale5", "Hscale6"},
  }};
  for (std::size_t d = 0; d < 6; ++d) {
    const bool rot = d >= 3;
    const Dim dk = rot ? dim::moment : dim::stiffness;   // moment per radian
    const Dim dc = rot ? Dim{1, 2, -1} : Dim{1, 0, -1};  // per (angular) velocity
    const Dim dq = rot ? dim::none : dim::length;        // elongation or angle
    const Dim dv = rot ? dim::rate : dim::velocity;      // (angular) velocity
    k.cards.push_back(
        card(blocks[d][0],
             {R(n[0][d], 1, 20, "linear stiffness; with fct_ID1 the stiffness of the time step").dims(dk),
              R(n[1][d], 21, 40, "linear damping coefficient").dims(dc),
              R(n[2][d], 41, 60, "amplification of the curve's force; 0 = 1 (1 without fct_ID1)"),
              R(n[3][d], 61, 80, "logarithmic rate amplification of the curve's force"),
              R(n[4][d], 81, 100, "velocity of the logarithmic amplification; 0 = 1").dims(dv)}));
    k.cards.push_back(
        card(blocks[d][1],
             {I(n[5][d], 1, 10, "force of the elongation f(dx); 0 = linear K").refs(IdKind::Other),
              I(n[6][d], 11, 20,
                "hardening flag: 0 elastic, 1 isotropic, 2 uncoupled, 4 kinematic, 5 residual elongation, 6 "
                "isotropic with nonlinear unloading, 7 elastic hysteresis (8 is refused)")
                  .allow({0, 1, 2, 4, 5, 6, 7, 8}),
              I(n[7][d], 21, 30, "amplification g(v) of the curve's force (E g(v/F))").refs(IdKind::Other),
              I(n[8][d], 31, 40, "H 4: lower yield force; 5: residual elongation; 6, 7: unloading")
                  .refs(IdKind::Other),
              I(n[9][d], 41, 50, "additional force of the velocity, Hscale g4(v/F)").refs(IdKind::Other),
              R(n[10][d], 61, 80, "failure elongation (angle) in compression (< 0); 0 = none").dims(dq),
              R(n[11][d], 81, 100, "failure elongation (angle) in tension (> 0); 0 = none").dims(dq)}));
    k.cards.push_back(
        card(blocks[d][2],
             {R(n[12][d], 1, 20, "velocity scale of the g(v) curves; 0 = 1").dims(dv),
              R(n[13][d], 21, 40, "scale of g(v) in the amplification (0 without fct_ID1)"),
              R(n[14][d], 41, 60, "abscissa scale of fct_ID1; 0 = 1").dims(dq),
              R(n[15][d], 61, 80, "ordinate scale of fct_ID4; 0 = 1").dims(rot ? dim::moment : dim::force)}));
  }
}

// Heat exchange coefficient and radiation factor of the TYPE7 thermal cards: power per area per kelvin
// (per kelvin^4 for the radiation factor), M T^-3.
constexpr Dim kHeatTransfer{1, 0, -3};

// ---------------------------------------------------------------------------------------------------------
// Run control, units, mesh
void add_control_and_mesh(std::vector<KeywordDecl>& t) {
  {
    KeywordDecl k = kw("/BEGIN", "start of the starter deck: run name, deck version and unit systems",
                       Header::None, false);
    k.singleton = true;
    k.cards = {
        card("card 1", {S("RUNNAME", 1, 100, "free run name; outputs are named after the input file")}),
        card("card 2", {I("INVERS", 1, 10, "deck format version; selects the layout of every keyword").must(),
                        I("IRUN", 11, 20, "run number of old layouts, read and not used")
                            .versions(kAnyVersion, 2020)
                            .unused()}),
        // Decks of version 90 have no unit cards: /UNIT/MASS, /UNIT/LENGTH and /UNIT/TIME name the units.
        card_v("card 3 (input units)", 100, kLastVersion,
               {S("input_mass", 1, 20, "mass unit the deck is written in (name or factor to kg)"),
                S("input_length", 21, 40, "length unit the deck is written in (name or factor to m)"),
                S("input_time", 41, 60, "time unit the deck is written in (name or factor to s)")}),
        card_v("card 4 (work units)", 100, kLastVersion,
               {S("work_mass", 1, 20, "mass unit the solver computes in"),
                S("work_length", 21, 40, "length unit the solver computes in"),
                S("work_time", 41, 60, "time unit the solver computes in")}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/TITLE", "model title printed in the listings", Header::None, false);
    k.singleton = true;
    k.cards = {card("card 1", {S("TITLE", 1, 100, "model title")})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/UNIT", "a named unit system that objects can refer to by their unit id", Header::Id,
                       true, "unit_ID");
    k.cards = {card("card 1", {S("MUNIT", 1, 20, "mass unit: a unit name or a factor relative to kg"),
                               S("LUNIT", 21, 40, "length unit: a unit name or a factor relative to m"),
                               S("TUNIT", 41, 60, "time unit: a unit name or a factor relative to s")})};
    t.push_back(std::move(k));
  }
  // The global units of decks of version 90 and older, one keyword per quantity; Radioss ignores them in
  // newer decks (so does radx, with a warning).
  struct GlobalUnit {
    std::string_view path;
    std::string_view meaning;
  };
  for (const GlobalUnit& u :
       {GlobalUnit{"/UNIT/MASS", "the deck's mass unit (version 90 and older), e.g. /UNIT/MASS/Mg"},
        GlobalUnit{"/UNIT/LENGTH", "the deck's length unit (version 90 and older), e.g. /UNIT/LENGTH/mm"},
        GlobalUnit{"/UNIT/TIME", "the deck's time unit (version 90 and older), e.g. /UNIT/TIME/s"}}) {
    KeywordDecl k = kw(u.path, u.meaning, Header::Word, false, "unit");
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/NODE", "node coordinates, one node per line", Header::UnitOnly, false, "unit_ID");
    k.tail = Tail::Records;
    k.record = card(
        "node",
        {I("node_ID", 1, 10, "user node id, positive and unique").refs(IdKind::Node).must().gt(0),
         R("X", 11, 30, "X coordinate").dims(dim::length), R("Y", 31, 50, "Y coordinate").dims(dim::length),
         R("Z", 51, 70, "Z coordinate").dims(dim::length)});
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/SHELL", "4-node shell elements of one part, one element per line", Header::PartId,
                       false, "part_ID");
    k.tail = Tail::Records;
    k.record =
        card("shell",
             {I("shell_ID", 1, 10, "element id").refs(IdKind::Element).must().gt(0),
              I("n1", 11, 20, "first node; the normal follows n1, n2, n3 by the right-hand rule")
                  .refs(IdKind::Node)
                  .must(),
              I("n2", 21, 30, "second node").refs(IdKind::Node).must(),
              I("n3", 31, 40, "third node").refs(IdKind::Node).must(),
              I("n4", 41, 50, "fourth node; 0 or equal to n3 makes a degenerate triangle").refs(IdKind::Node),
              R("PHI", 61, 80, "material direction angle in degrees"),
              R("Thick", 81, 100, "element thickness; 0 takes the property thickness").dims(dim::length)});
    t.push_back(std::move(k));
  }
  {
    // Columns as the reference reader cuts the card (71-90 and 91-100), not as its comment ruler shows them
    // (61-80 and 81-100). Right-justified numbers of up to 10 characters read the same either way.
    KeywordDecl k = kw("/SH3N", "3-node shell elements of one part, one element per line", Header::PartId,
                       false, "part_ID");
    k.tail = Tail::Records;
    k.record = card(
        "sh3n", {I("tria_ID", 1, 10, "element id").refs(IdKind::Element).must().gt(0),
                 I("n1", 11, 20, "first node; the normal follows n1, n2, n3 by the right-hand rule")
                     .refs(IdKind::Node)
                     .must(),
                 I("n2", 21, 30, "second node").refs(IdKind::Node).must(),
                 I("n3", 31, 40, "third node").refs(IdKind::Node).must(),
                 R("PHI", 71, 90, "material direction angle in degrees"),
                 R("Thick", 91, 100, "element thickness; 0 takes the property thickness").dims(dim::length)});
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/BRICK", "8-node solid elements of one part, one element per line", Header::PartId,
                       false, "part_ID");
    k.tail = Tail::Records;
    k.record = card(
        "brick",
        {I("brick_ID", 1, 10, "element id").refs(IdKind::Element).must().gt(0),
         I("n1", 11, 20, "node 1 (n1..n4 form one face)").refs(IdKind::Node).must(),
         I("n2", 21, 30, "node 2").refs(IdKind::Node).must(),
         I("n3", 31, 40, "node 3").refs(IdKind::Node).must(),
         I("n4", 41, 50, "node 4").refs(IdKind::Node).must(),
         I("n5", 51, 60, "node 5, joined to n1 (repeated nodes give degenerate shapes)").refs(IdKind::Node),
         I("n6", 61, 70, "node 6, joined to n2").refs(IdKind::Node),
         I("n7", 71, 80, "node 7, joined to n3").refs(IdKind::Node),
         I("n8", 81, 90, "node 8, joined to n4").refs(IdKind::Node)});
    t.push_back(std::move(k));
  }
  {
    // Columns as OpenRadioss's reader cuts the card (hm_read_solid.F: id, then the nodes 10 wide).
    KeywordDecl k = kw("/TETRA4", "4-node tetrahedra of one part (a /PROP/SOLID part), one element per line",
                       Header::PartId, false, "part_ID");
    k.tail = Tail::Records;
    k.record = card(
        "tetra4",
        {I("tetra_ID", 1, 10, "element id, unique among all elements").refs(IdKind::Element).must().gt(0),
         I("n1", 11, 20, "node 1").refs(IdKind::Node).must(),
         I("n2", 21, 30, "node 2").refs(IdKind::Node).must(),
         I("n3", 31, 40,
           "node 3; the right-hand normal of n1 n2 n3 points away from n4 (otherwise the "
           "starter swaps n2 and n4, as Radioss does)")
             .refs(IdKind::Node)
             .must(),
         I("n4", 41, 50, "node 4").refs(IdKind::Node).must()});
    t.push_back(std::move(k));
  }
  {
    // Three lines per element, as OpenRadioss's card (hm_cfg_files .../ELEM/bric20.cfg): the id and the 8
    // corners, then the mid-side nodes 9-16 and 17-20 from column 1. Line 2 is declared at columns 101-180
    // and line 3 at 201-240 (KeywordDecl::record_lines).
    KeywordDecl k = kw("/BRIC20",
                       "20-node quadratic bricks of one part (a /PROP/SOLID part), three lines per element: "
                       "id and corners n1-n8; mid-side nodes n9-n16; n17-n20",
                       Header::PartId, false, "part_ID");
    k.tail = Tail::Records;
    k.record_lines = 3;
    std::vector<FieldDecl> f = {
        I("brick20_ID", 1, 10, "element id, unique among all solid elements")
            .refs(IdKind::Element)
            .must()
            .gt(0),
        I("n1", 11, 20, "corner 1 (n1..n4 form one face, as /BRICK)").refs(IdKind::Node).must(),
        I("n2", 21, 30, "corner 2").refs(IdKind::Node).must(),
        I("n3", 31, 40, "corner 3").refs(IdKind::Node).must(),
        I("n4", 41, 50, "corner 4").refs(IdKind::Node).must(),
        I("n5", 51, 60, "corner 5, joined to n1").refs(IdKind::Node).must(),
        I("n6", 61, 70, "corner 6, joined to n2").refs(IdKind::Node).must(),
        I("n7", 71, 80, "corner 7, joined to n3").refs(IdKind::Node).must(),
        I("n8", 81, 90, "corner 8, joined to n4").refs(IdKind::Node).must(),
        I("n9", 101, 110, "line 2, columns 1-10: mid-side node of edge n1-n2").refs(IdKind::Node).must(),
        I("n10", 111, 120, "line 2, columns 11-20: edge n2-n3").refs(IdKind::Node).must(),
        I("n11", 121, 130, "line 2, columns 21-30: edge n3-n4").refs(IdKind::Node).must(),
        I("n12", 131, 140, "line 2, columns 31-40: edge n4-n1").refs(IdKind::Node).must(),
        I("n13", 141, 150, "line 2, columns 41-50: edge n1-n5").refs(IdKind::Node).must(),
        I("n14", 151, 160, "line 2, columns 51-60: edge n2-n6").refs(IdKind::Node).must(),
        I("n15", 161, 170, "line 2, columns 61-70: edge n3-n7").refs(IdKind::Node).must(),
        I("n16", 171, 180, "line 2, columns 71-80: edge n4-n8").refs(IdKind::Node).must(),
        I("n17", 201, 210, "line 3, columns 1-10: edge n5-n6").refs(IdKind::Node).must(),
        I("n18", 211, 220, "line 3, columns 11-20: edge n6-n7").refs(IdKind::Node).must(),
        I("n19", 221, 230, "line 3, columns 21-30: edge n7-n8").refs(IdKind::Node).must(),
        I("n20", 231, 240, "line 3, columns 31-40: edge n8-n5").refs(IdKind::Node).must()};
    k.record = card("bric20", std::move(f));
    t.push_back(std::move(k));
  }
  {
    // Columns as OpenRadioss's reader cuts the card (hm_read_spring.F): id, then the nodes 10 wide.
    KeywordDecl k = kw("/SPRING", "2-node spring elements of one part (a /PROP/SPRING part), one per line",
                       Header::PartId, false, "part_ID");
    k.tail = Tail::Records;
    k.record = card(
        "spring",
        {I("spring_ID", 1, 10, "element id").refs(IdKind::Element).must().gt(0),
         I("n1", 11, 20, "first node").refs(IdKind::Node).must(),
         I("n2", 21, 30, "second node").refs(IdKind::Node).must(),
         I("n3", 31, 40, "orientation node (used by TYPE8 and TYPE13 springs only)").refs(IdKind::Node)});
    t.push_back(std::move(k));
  }
  {
    // Columns as OpenRadioss's reader cuts the card (hm_read_beam.F): id, then the nodes 10 wide.
    KeywordDecl k = kw("/BEAM", "2-node beam elements of one part (a /PROP/BEAM part), one per line",
                       Header::PartId, false, "part_ID");
    k.tail = Tail::Records;
    k.record =
        card("beam", {I("beam_ID", 1, 10, "element id").refs(IdKind::Element).must().gt(0),
                      I("n1", 11, 20, "first node").refs(IdKind::Node).must(),
                      I("n2", 21, 30, "second node").refs(IdKind::Node).must(),
                      I("n3", 31, 40,
                        "orientation node: the local y axis points from n1 towards it; blank: global Y (Z "
                        "for a beam along Y)")
                          .refs(IdKind::Node)});
    t.push_back(std::move(k));
  }
  {
    // Columns as OpenRadioss's reader cuts the card (hm_read_truss.F): id, then the nodes 10 wide.
    KeywordDecl k = kw("/TRUSS", "2-node truss elements of one part (a /PROP/TRUSS part), one per line",
                       Header::PartId, false, "part_ID");
    k.tail = Tail::Records;
    k.record = card("truss", {I("truss_ID", 1, 10, "element id").refs(IdKind::Element).must().gt(0),
                              I("n1", 11, 20, "first node").refs(IdKind::Node).must(),
                              I("n2", 21, 30, "second node").refs(IdKind::Node).must()});
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/PART", "a part: the property and material of a set of elements", Header::IdUnit,
                       true, "part_ID");
    k.cards = {card(
        "card 1",
        {I("prop_ID", 1, 10, "property (/PROP) of the part's elements").refs(IdKind::Property).must(),
         I("mat_ID", 11, 20, "material (/MAT) of the part's elements; 0 only for spring parts")
             .refs(IdKind::Material),
         I("subset_ID", 21, 30, "subset the part belongs to; 0 = top level").refs(IdKind::Other),
         R("Thick", 31, 50, "virtual thickness used only for contact gaps; 0 = none").dims(dim::length)})};
    t.push_back(std::move(k));
  }
}

// ---------------------------------------------------------------------------------------------------------
// Properties and materials
void add_properties_and_materials(std::vector<KeywordDecl>& t) {
  {
    // OpenRadioss hm_read_prop03.F; prop_p3_beam.cfg (one layout from radioss51 on).
    KeywordDecl k =
        kw("/PROP/BEAM",
           "beam property (TYPE3): section area and inertias, damping, shear and released rotations",
           Header::IdUnit, true, "prop_ID");
    k.aliases = {"/PROP/TYPE3"};
    k.cards = {
        card("card 1",
             {I("Ismstr", 11, 20,
                "strain formulation: 0, 2 and 4 large strain (radx runs these); 1 and 3 small strain")
                  .allow({0, 1, 2, 3, 4})}),
        card("card 2", {R("Dm", 1, 20, "membrane damping (fraction of the critical damping)").dims(dim::none),
                        R("Df", 21, 40, "flexural damping; 0 = 0.01").dims(dim::none)}),
        card("card 3", {R("Area", 1, 20, "cross-section area").dims(dim::area).must().gt(0.0),
                        R("Iyy", 21, 40, "second moment of area about the local y axis (bending in z)")
                            .dims(Dim{0, 4, 0})
                            .must()
                            .gt(0.0),
                        R("Izz", 41, 60, "second moment of area about the local z axis (bending in y)")
                            .dims(Dim{0, 4, 0})
                            .must()
                            .gt(0.0),
                        R("Ixx", 61, 80, "torsion constant").dims(Dim{0, 4, 0}).must().gt(0.0)}),
        card("card 4",
             {I("Wx1", 4, 4, "1: rotation about x released (at either node: torsion)").allow({0, 1}),
              I("Wy1", 5, 5, "1: rotation about y released at node 1").allow({0, 1}),
              I("Wz1", 6, 6, "1: rotation about z released at node 1").allow({0, 1}),
              I("Wx2", 8, 8, "1: rotation about x released (at either node: torsion)").allow({0, 1}),
              I("Wy2", 9, 9, "1: rotation about y released at node 2").allow({0, 1}),
              I("Wz2", 10, 10, "1: rotation about z released at node 2").allow({0, 1}),
              I("Ishear", 11, 20, "0: shear deformation taken into account; 1: neglected").allow({0, 1})})};
    t.push_back(std::move(k));
  }
  {
    // OpenRadioss hm_read_prop02.F; prop_p2_trus.cfg (one layout from radioss51 on).
    KeywordDecl k = kw("/PROP/TRUSS", "truss property (TYPE2): cross-section area (axial force only)",
                       Header::IdUnit, true, "prop_ID");
    k.aliases = {"/PROP/TYPE2"};
    k.cards = {card(
        "card 1", {R("Area", 1, 20, "initial cross-section area").dims(dim::area).must().gt(0.0),
                   R("Gap", 21, 40,
                     "initial gap: the truss carries no force until it has shortened by Gap (a gap element)")
                       .dims(dim::length)
                       .not_implemented()})};
    t.push_back(std::move(k));
  }
  {
    // OpenRadioss hm_read_prop04.F; the layouts of prop_p4_spring.cfg (fct_ID4 and Hscale from 120 on).
    KeywordDecl k = kw("/PROP/SPRING", "spring property (TYPE4): mass, stiffness or force curve, damping",
                       Header::IdUnit, true, "prop_ID");
    k.aliases = {"/PROP/TYPE4"};
    k.cards = {
        card("card 1",
             {R("M", 1, 20, "spring mass, half to each node (per unit length with Ileng 1); must be > 0")
                  .dims(dim::mass),
              I("sens_ID", 51, 60, "sensor that activates or deactivates the spring; 0 = none")
                  .refs(IdKind::Other)
                  .not_implemented(),
              I("Isflag", 61, 70, "sensor flag").allow({0, 1, 2}).unused(),
              I("Ileng", 71, 80, "1: mass, stiffness, damping and curves per unit length").allow({0, 1})}),
        card("card 2",
             {R("K", 1, 20,
                "linear stiffness; with fct_ID1 the stiffness of the time step (at least the curve's slope)")
                  .dims(dim::stiffness),
              R("C", 21, 40, "linear damping coefficient (force per velocity)").dims(Dim{1, 0, -1}),
              R("A", 41, 60, "amplification of the curve's force; 0 = 1 (1 without fct_ID1)").dims(dim::none),
              R("B", 61, 80, "logarithmic rate amplification of the curve's force (0 without fct_ID1)"),
              R("D", 81, 100, "velocity of the logarithmic amplification; 0 = 1").dims(dim::velocity)}),
        card_v(
            "card 3", kAnyVersion, 110,
            {I("fct_ID1", 1, 10, "force of the elongation f(dx); 0 = linear K").refs(IdKind::Other),
             I("H", 11, 20,
               "hardening flag: 0 elastic, 1 isotropic, 2 uncoupled, 4 kinematic, 5 residual elongation, "
               "6 isotropic with nonlinear unloading, 7 elastic hysteresis, 8 elastic of the total length")
                 .allow({0, 1, 2, 4, 5, 6, 7, 8}),
             I("fct_ID2", 21, 30, "amplification g(v) of the curve's force (E g(v/F))").refs(IdKind::Other),
             I("fct_ID3", 31, 40, "H 4: lower yield force; 5: residual elongation; 6, 7: unloading")
                 .refs(IdKind::Other),
             R("delta_min", 61, 80, "failure elongation in compression (< 0); 0 = none").dims(dim::length),
             R("delta_max", 81, 100, "failure elongation in tension (> 0); 0 = none").dims(dim::length)}),
        card_v(
            "card 3", 120, kLastVersion,
            {I("fct_ID1", 1, 10, "force of the elongation f(dx); 0 = linear K").refs(IdKind::Other),
             I("H", 11, 20,
               "hardening flag: 0 elastic, 1 isotropic, 2 uncoupled, 4 kinematic, 5 residual elongation, "
               "6 isotropic with nonlinear unloading, 7 elastic hysteresis, 8 elastic of the total length")
                 .allow({0, 1, 2, 4, 5, 6, 7, 8}),
             I("fct_ID2", 21, 30, "amplification g(v) of the curve's force (E g(v/F))").refs(IdKind::Other),
             I("fct_ID3", 31, 40, "H 4: lower yield force; 5: residual elongation; 6, 7: unloading")
                 .refs(IdKind::Other),
             I("fct_ID4", 41, 50, "additional force of the velocity, Hscale g4(v/F)").refs(IdKind::Other),
             R("delta_min", 61, 80, "failure elongation in compression (< 0); 0 = none").dims(dim::length),
             R("delta_max", 81, 100, "failure elongation in tension (> 0); 0 = none").dims(dim::length)}),
        card("card 4",
             {R("F", 1, 20, "velocity scale of fct_ID2 and fct_ID4; 0 = 1").dims(dim::velocity),
              R("E", 21, 40, "scale of g(v) in the amplification (0 without fct_ID1)"),
              R("Ascale", 41, 60, "abscissa (elongation) scale of fct_ID1; 0 = 1").dims(dim::length),
              R("Hscale", 61, 80, "ordinate scale of fct_ID4; 0 = 1").dims(dim::force).versions(120)}),
    };
    t.push_back(std::move(k));
  }
  {
    // OpenRadioss hm_read_prop08.F; the layouts of prop_p8_spr_gene.cfg from 120 on (Ifail2 from 2018 on).
    // Six blocks of three cards, one per degree of freedom (1..3 translations X Y Z, 4..6 rotations), with
    // the fields of /PROP/SPRING numbered by degree of freedom as the Radioss manual numbers them.
    KeywordDecl k = kw("/PROP/SPR_GENE",
                       "general spring property (TYPE8): six uncoupled springs along and about the axes of a "
                       "fixed frame",
                       Header::IdUnit, true, "prop_ID");
    k.aliases = {"/PROP/TYPE8"};
    k.since = 120;
    k.cards = {card(
        "card 1",
        {R("M", 1, 20, "spring mass, half to each node; must be > 0").dims(dim::mass),
         R("Inertia", 21, 40, "rotational inertia, half to each node; > 0 when a rotation has K or C")
             .dims(dim::inertia),
         I("skew_ID", 41, 50, "frame of the six springs (a /SKEW/FIX); 0 = global axes").refs(IdKind::Other),
         I("sens_ID", 51, 60, "sensor that activates or deactivates the spring; 0 = none")
             .refs(IdKind::Other)
             .not_implemented(),
         I("Isflag", 61, 70, "sensor flag").allow({0, 1, 2}).unused(),
         I("Ifail", 71, 80, "failure criterion: 0 each direction alone, 1 the sum of squares").allow({0, 1}),
         I("Ifail2", 81, 90, "failure by 0 elongation (1 by force and 2 by energy are not implemented)")
             .versions(2018)
             .allow({0, 1, 2})
             .not_implemented(),
         I("Iequil", 91, 100, "1: moment equilibrium of the shear forces (not implemented)")
             .allow({0, 1})
             .not_implemented()})};
    add_six_spring_laws(k, kSprGeneBlocks);
    k.cards.push_back(card("strain-rate filter",
                           {I("Fsmooth", 1, 10, "smoothing of the failure criterion (not implemented)")
                                .allow({0, 1})
                                .not_implemented(),
                            R("Fcut", 11, 30, "cutoff frequency of Fsmooth").dims(dim::rate).unused()}));
    t.push_back(std::move(k));
  }
  {
    // OpenRadioss hm_read_prop13.F; the layouts of prop_p13_spr_beam.cfg from 120 on (Asrate and Israte from
    // 2018 on). The six laws X (tension), Y Z (shear), RX (torsion), RY RZ (bending) act in a frame that
    // follows the spring; the cards after the six blocks only serve the failure modes Ifail2 1..3.
    KeywordDecl k = kw("/PROP/SPR_BEAM",
                       "beam-type spring property (TYPE13): six laws in a frame that follows the spring, the "
                       "shear forces balanced by end moments",
                       Header::IdUnit, true, "prop_ID");
    k.aliases = {"/PROP/TYPE13"};
    k.since = 120;
    k.cards = {card(
        "card 1",
        {R("M", 1, 20, "spring mass, half to each node; must be > 0").dims(dim::mass),
         R("Inertia", 21, 40,
           "rotational inertia, half to each node; > 0 when a shear or rotation has K or C")
             .dims(dim::inertia),
         I("skew_ID", 41, 50, "skew whose Y axis (X if Y lies along the spring) orients the frame without n3")
             .refs(IdKind::Other),
         I("sens_ID", 51, 60, "sensor that activates or deactivates the spring; 0 = none")
             .refs(IdKind::Other)
             .not_implemented(),
         I("Isflag", 61, 70, "sensor flag").allow({0, 1, 2}).unused(),
         I("Ifail", 71, 80, "failure criterion: 0 each direction alone, 1 the sum of squares").allow({0, 1}),
         I("Ileng", 81, 90, "1: mass, stiffness, damping and curves per unit length (not implemented)")
             .allow({0, 1})
             .not_implemented(),
         I("Ifail2", 91, 100,
           "failure mode: 0 by elongation (1 with velocity, 2 by force, 3 by energy: not implemented)")
             .allow({0, 1, 2, 3})
             .not_implemented()})};
    add_six_spring_laws(k, kSprBeamBlocks);
    k.cards.push_back(card(
        "reference velocities",
        {R("Vo", 1, 20, "reference velocity of the failure modes Ifail2 1..3").dims(dim::velocity).unused(),
         R("Wo", 21, 40, "reference angular velocity of the failure modes Ifail2 1..3")
             .dims(dim::rate)
             .unused(),
         R("Asrate", 41, 60, "cutoff frequency of the failure criterion's filter")
             .dims(dim::rate)
             .versions(2018)
             .unused(),
         I("Israte", 61, 70, "filter of the failure criterion (not implemented)")
             .versions(2018)
             .allow({0, 1})
             .not_implemented()}));
    static constexpr std::array<std::array<std::string_view, 5>, 6> fail = {{
        {"failure X", "c1", "n1", "alpha1", "beta1"},
        {"failure Y", "c2", "n2", "alpha2", "beta2"},
        {"failure Z", "c3", "n3", "alpha3", "beta3"},
        {"failure RX", "c4", "n4", "alpha4", "beta4"},
        {"failure RY", "c5", "n5", "alpha5", "beta5"},
        {"failure RZ", "c6", "n6", "alpha6", "beta6"},
    }};
    for (const auto& f : fail)
      k.cards.push_back(
          card(f[0], {R(f[1], 1, 20, "velocity term of the failure limits (Ifail2 1..3)").unused(),
                      R(f[2], 21, 40, "exponent of that term").unused(),
                      R(f[3], 41, 60, "weight of this direction (Ifail2 1..3)").unused(),
                      R(f[4], 61, 80, "exponent of this direction (Ifail2 1..3)").unused()}));
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/PROP/SHELL", "shell property: formulation flags, hourglass, thickness",
                       Header::IdUnit, true, "prop_ID");
    k.aliases = {"/PROP/TYPE1"};
    k.cards = {
        card("card 1", {I("Ishell", 1, 10, "4-node shell formulation; 0 takes /DEF_SHELL, then 1")
                            .allow({0, 1, 2, 3, 4, 12, 22, 23, 24}),
                        I("Ismstr", 11, 20,
                          "shell strain formulation; 0 takes /DEF_SHELL, then 2; -1 runs as 4 (Radioss keeps "
                          "it and none of its shell paths treats it apart)")
                            .allow({-1, 0, 1, 2, 3, 4, 10}),
                        I("Ish3n", 21, 30, "3-node shell formulation; 0 takes /DEF_SHELL, then 2")
                            .allow({0, 1, 2, 30, 31}),
                        I("Idrill", 31, 40, "drilling stiffness: 1 on, 2 off; 0 takes /DEF_SHELL, then off")
                            .versions(110)
                            .allow({0, 1, 2}),
                        I("Ipinch", 41, 50, "pinching degree of freedom (QBAT only)")
                            .versions(2020)
                            .allow({0, 1})
                            .unused(),
                        R("P_Thick_Fail", 61, 80,
                          "failed fraction of thickness (>0) or of points (<0) that deletes the element")
                            .versions(2018)
                            .zero_is(0.999999)}),
        card("card 2",
             {R("Hm", 1, 20, "membrane hourglass coefficient").zero_is(0.01),
              R("Hf", 21, 40, "out-of-plane hourglass coefficient").zero_is(0.01),
              R("Hr", 41, 60, "rotational hourglass coefficient").zero_is(0.01),
              R("Dm", 61, 80, "membrane damping coefficient; 0 = none"),
              R("Dn", 81, 100, "numerical damping of QBAT and QEPH; 0 takes the formulation default")}),
        card("card 3",
             {I("N", 1, 10, "integration points through the thickness; 0 = global plasticity").ge(0).le(10),
              I("Istrain", 11, 20, "strain output flag, forced on by the reference starter")
                  .versions(kAnyVersion, 2023)
                  .unused(),
              R("Thick", 21, 40, "shell thickness, used where the element gives none").dims(dim::length),
              R("Ashear", 41, 60, "transverse shear correction factor").zero_is(5.0 / 6.0),
              I("Ithick", 71, 80, "1 = thickness follows membrane strain, 2 = constant; 0 takes /DEF_SHELL")
                  .allow({0, 1, 2}),
              I("Iplas", 81, 90,
                "plane-stress plasticity: 1 iterative projection, 2 radial return; 0 takes /DEF_SHELL")
                  .allow({0, 1, 2}),
              I("Ipos", 91, 100, "reference plane of the shell (0 mid-surface, 3 top, 4 bottom)")
                  .versions(2024)
                  .not_implemented()}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/PROP/SOLID", "solid property: formulation flags, bulk viscosity, hourglass",
                       Header::IdUnit, true, "prop_ID");
    k.aliases = {"/PROP/TYPE14"};
    k.cards = {
        card(
            "card 1",
            {I("Isolid", 1, 10, "8-node solid formulation; 0 takes /DEF_SOLID, then 1")
                 .allow({0, 1, 2, 12, 14, 15, 16, 17, 18, 24}),
             I("Ismstr", 11, 20, "solid strain formulation; 0 takes /DEF_SOLID, then 4")
                 .allow({0, 1, 2, 3, 4, 10, 11, 12}),
             I("Iale", 21, 30, "0 Lagrange, 1 ALE, 2 Euler")
                 .versions(2022)
                 .allow({0, 1, 2})
                 .not_implemented(),
             I("Icpre", 31, 40, "constant-pressure option (3 = off); 0 takes /DEF_SOLID").allow({0, 1, 2, 3}),
             I("Itetra10", 41, 50, "10-node tetra formulation; 0 takes /DEF_SOLID")
                 .versions(2019)
                 .allow({0, 2, 1000})
                 .unused(),
             I("Inpts", 51, 60, "integration points coded 100r + 10s + t; 0 = formulation default"),
             // Any value is read as Radioss reads it (negative: the integration flag of older decks; 2 and
             // unexpected values mean 1000); check_formulations.cpp refuses 1, 3 and 10 when a tetra uses it.
             I("Itetra4", 61, 70,
               "4-node tetra formulation: 1000 (default) constant strain; 1 and 3 (nodal pressure) and 10 "
               "(as a tetra10) are refused; 0 takes /DEF_SOLID")
                 .versions(100),
             I("Iframe", 71, 80, "1 non-co-rotational, 2 co-rotational; 0 takes /DEF_SOLID").allow({0, 1, 2}),
             R("dn", 81, 100, "numerical damping of HEPH (Isolid 24); 0 takes the formulation default")}),
        card("card 2", {R("qa", 1, 20, "quadratic bulk viscosity coefficient").zero_is(1.1),
                        R("qb", 21, 40, "linear bulk viscosity coefficient").zero_is(0.05),
                        R("h", 41, 60, "hourglass coefficient of Isolid 1 and 2").zero_is(0.1),
                        R("Lambda", 61, 80, "numerical (Navier-Stokes) viscosity lambda; 0 = off")
                            .versions(120)
                            .not_implemented(),
                        R("Mu", 81, 100, "numerical (Navier-Stokes) viscosity mu; 0 = off")
                            .versions(120)
                            .not_implemented()}),
        card("card 3",
             {R("deltaT_min", 1, 20, "minimum element time step").dims(dim::time).not_implemented(),
              I("Istrain", 21, 30, "strain output flag").versions(100, 2022).unused(),
              I("Ihkt", 31, 40, "hourglass formulation option of old layouts").versions(120, 2022).unused(),
              R("vdef_min", 21, 40, "distortion control: lower volumetric deformation limit; 0 = off")
                  .versions(2023)
                  .unused(),
              R("vdef_max", 41, 60, "distortion control: upper volumetric deformation limit; 0 = off")
                  .versions(2023)
                  .unused(),
              R("ASP_max", 61, 80, "distortion control: largest aspect ratio; 0 = off")
                  .versions(2023)
                  .unused(),
              R("COL_min", 81, 100, "distortion control: smallest collapse ratio; 0 = off")
                  .versions(2023)
                  .unused()}),
        card_v("card 4", 140, kLastVersion,
               {I("Ndir", 1, 10, "solid-to-SPH conversion: particles per direction").not_implemented(),
                I("sphpart_ID", 11, 20, "solid-to-SPH conversion: SPH part")
                    .refs(IdKind::Part)
                    .not_implemented(),
                I("Icontrol", 21, 30, "distortion control: 1 on, 2 or 0 off")
                    .versions(2025)
                    .allow({0, 1, 2})
                    .unused()}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/MAT/LAW1", "linear elastic isotropic material", Header::IdUnit, true, "mat_ID");
    k.aliases = {"/MAT/ELAST", "/MAT/LAW01"};
    k.cards = {
        card("card 1", {R("RHO_I", 1, 20, "initial density").must().gt(0.0).dims(dim::density),
                        R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I").dims(dim::density)}),
        card("card 2", {R("E", 1, 20, "Young's modulus").must().gt(0.0).dims(dim::pressure),
                        R("nu", 21, 40, "Poisson's ratio; exactly 0.5 is taken as 0.499")}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/MAT/LAW2", "Johnson-Cook elasto-plastic material", Header::IdUnit, true, "mat_ID");
    k.aliases = {"/MAT/PLAS_JOHNS", "/MAT/LAW02"};
    k.cards = {
        // Up to 130 the reference reader pre-reads columns 11-20, not 21-40, to decide whether the card
        // carries RHO_ref: a left-justified RHO_I leaves them blank and RHO_ref is then not read.
        card("card 1",
             {R("RHO_I", 1, 20, "initial density").must().gt(0.0).dims(dim::density),
              R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I")
                  .versions(kAnyVersion, 130)
                  .read_if_text(11, 20)
                  .dims(dim::density),
              R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I").versions(140).dims(dim::density)}),
        card("card 2",
             {R("E", 1, 20, "Young's modulus").must().gt(0.0).dims(dim::pressure),
              R("nu", 21, 40, "Poisson's ratio; exactly 0.5 is taken as 0.499"),
              I("Iflag", 41, 50, "card 3 input: 0 gives a, b, n; 1 gives yield, UTS and strain at UTS")
                  .versions(140)
                  .allow({0, 1}),
              I("flagVP", 51, 60, "strain rate used: 1 plastic, 2 total, 3 deviatoric")
                  .versions(2023)
                  .zero_is(2)
                  .allow({0, 1, 2, 3}),
              R("Pmin", 61, 80, "pressure cut-off in tension")
                  .versions(2025)
                  .zero_is(-1e20)
                  .dims(dim::pressure)}),
        // Radioss reads a, b, n for every Iflag but 1: an Iflag out of range is refused once, on its own
        // field.
        card_if("card 3 (Iflag 0)", when_ne("Iflag", 1),
                {R("a", 1, 20, "initial yield stress").gt(0.0).dims(dim::pressure),
                 R("b", 21, 40, "hardening modulus").dims(dim::pressure),
                 R("n", 41, 60, "hardening exponent").zero_is(1.0).le(1.0),
                 R("EPS_p_max", 61, 80, "plastic strain at which the element fails").zero_is(1e20),
                 R("SIG_max0", 81, 100, "cap on the flow stress").zero_is(1e20).dims(dim::pressure)}),
        card_if("card 3 (Iflag = 1)", when_eq("Iflag", 1),
                {R("SIG_Y", 1, 20, "initial yield stress").dims(dim::pressure),
                 R("UTS", 21, 40, "ultimate tensile stress").dims(dim::pressure),
                 R("EUTS", 41, 60, "engineering strain at UTS"),
                 R("EPS_p_max", 61, 80, "plastic strain at which the element fails").zero_is(1e20),
                 R("SIG_max0", 81, 100, "cap on the flow stress").zero_is(1e20).dims(dim::pressure)}),
        card(
            "card 4",
            {R("c", 1, 20, "strain-rate coefficient; 0 = no rate effect"),
             R("EPS_DOT_0", 21, 40, "reference strain rate (needed when c is not 0)").dims(dim::rate),
             I("ICC", 41, 50, "1: the rate term also scales SIG_max0; 2: it does not")
                 .zero_is(1)
                 .allow({0, 1, 2}),
             I("Fsmooth", 51, 60, "strain-rate filtering flag (filtering is on whenever c is not 0)")
                 .allow({0, 1})
                 .unused(),
             R("F_cut", 61, 80, "cut-off frequency of the strain-rate filter; 0 = no filter").dims(dim::rate),
             R("Chard", 81, 100, "hardening mix: 0 isotropic to 1 kinematic")
                 .versions(100)
                 .ge(0.0)
                 .le(1.0)
                 .not_implemented()}),
        card(
            "card 5",
            {R("m", 1, 20, "temperature softening exponent").zero_is(1.0),
             R("T_melt", 21, 40, "melting temperature (kelvin)").zero_is(1e20),
             R("rhoC_p", 41, 60, "density times specific heat; 0 = no adiabatic heating")
                 .dims(dim::heat_capacity_per_volume),
             R("T_r", 61, 80, "reference (initial) temperature (kelvin); 0 or less means 300").zero_is(300.0),
             R("T_max", 81, 100, "largest temperature (kelvin)").versions(2025).zero_is(1e20)}),
    };
    t.push_back(std::move(k));
  }
}

// Names of the entries of /MAT/PLAS_TAB's curve lists: "fct_ID1" .. "fct_ID100", "Fscale1" .., "Eps_dot1" ..
// The declarations hold string_views, so the names live as long as the keyword table (built once).
constexpr int kPlasTabMaxCurves = 100;  // OpenRadioss hm_read_mat36.F refuses more
std::string_view plas_tab_name(int list, int k) {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const char* base : {"fct_ID", "Fscale", "Eps_dot"})
      for (int i = 1; i <= kPlasTabMaxCurves; ++i) v.push_back(base + std::to_string(i));
    return v;
  }();
  return names[static_cast<std::size_t>(list * kPlasTabMaxCurves + k)];
}

// Names of /FAIL/TAB's rate lines: "fct_ID1" .. "fct_ID100", "Fscale1" .., "Epsdot1" .., and the card names.
constexpr int kFailTabMaxRates = 100;  // OpenRadioss hm_read_fail_tab_old.F: MAXFUNC
std::string_view fail_tab_name(int list, int k) {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const char* base : {"fct_ID", "Fscale", "Epsdot", "rate line "})
      for (int i = 1; i <= kFailTabMaxRates; ++i) v.push_back(base + std::to_string(i));
    return v;
  }();
  return names[static_cast<std::size_t>(list * kFailTabMaxRates + k)];
}

// /MAT/PLAS_TAB's three lists (functions in 10-column cells, then scale factors and strain rates in
// 20-column cells), 5 entries a line, as many lines as N_funct needs: line j is read when N_funct > 5 j.
void add_plas_tab_lists(KeywordDecl& k) {
  static const std::vector<std::string> card_names = [] {
    std::vector<std::string> v;
    for (const char* what : {"functions", "scale factors", "strain rates"})
      for (int j = 0; j < kPlasTabMaxCurves / 5; ++j)
        v.push_back(std::string(what) + " " + std::to_string(5 * j + 1) + "-" + std::to_string(5 * j + 5));
    return v;
  }();
  for (int list = 0; list < 3; ++list) {
    for (int j = 0; j < kPlasTabMaxCurves / 5; ++j) {
      std::vector<FieldDecl> f;
      for (int c = 0; c < 5; ++c) {
        const int i = 5 * j + c;
        if (list == 0) {
          f.push_back(
              I(plas_tab_name(0, i), 10 * c + 1, 10 * c + 10, "yield curve sigma_y(eps_p) of this rate")
                  .refs(IdKind::Other));
        } else if (list == 1) {
          f.push_back(
              R(plas_tab_name(1, i), 20 * c + 1, 20 * c + 20, "scale factor of that curve's ordinates")
                  .zero_is(1.0)
                  .dims(dim::pressure));
        } else {
          f.push_back(R(plas_tab_name(2, i), 20 * c + 1, 20 * c + 20, "strain rate of that curve")
                          .ge(0.0)
                          .dims(dim::rate));
        }
      }
      k.cards.push_back(card_if(card_names[static_cast<std::size_t>(list * (kPlasTabMaxCurves / 5) + j)],
                                when_gt("N_funct", 5 * j), std::move(f)));
    }
  }
}

void add_plas_tab_and_failure(std::vector<KeywordDecl>& t) {
  {
    KeywordDecl k = kw("/MAT/LAW36", "tabulated elasto-plastic material: yield curves per strain rate",
                       Header::IdUnit, true, "mat_ID");
    k.aliases = {"/MAT/PLAS_TAB"};
    k.cards = {
        card("card 1", {R("RHO_I", 1, 20, "initial density").must().gt(0.0).dims(dim::density),
                        R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I").dims(dim::density)}),
        card("card 2",
             {R("E", 1, 20, "Young's modulus").must().gt(0.0).dims(dim::pressure),
              R("nu", 21, 40, "Poisson's ratio; exactly 0.5 is taken as 0.499"),
              R("Eps_p_max", 41, 60, "plastic strain at which the element fails; 0 = never")
                  .zero_is(1e20)
                  .ge(0.0),
              R("Eps_t", 61, 80, "tension failure: principal strain where the damage starts; 0 = none")
                  .not_implemented(),
              R("Eps_m", 81, 100, "tension failure: principal strain where the stress is zero; 0 = none")
                  .not_implemented()}),
        card(
            "card 3",
            {I("N_funct", 1, 10, "number of yield curves (strain rates), 1 to 100").must().ge(1).le(100),
             I("Fsmooth", 11, 20, "strain-rate interpolation: 0 or 1 linear, 2 logarithmic").allow({0, 1, 2}),
             R("Chard", 21, 40, "hardening mix: 0 isotropic to 1 kinematic")
                 .ge(0.0)
                 .le(1.0)
                 .not_implemented(),
             R("Fcut", 41, 60, "cut-off frequency of the strain-rate filter; 0 = 10 kHz with several curves")
                 .ge(0.0)
                 .dims(dim::rate),
             R("Eps_f", 61, 80, "tension failure: principal strain where the element fails; 0 = none")
                 .not_implemented(),
             I("VP", 91, 100, "strain rate of the curves: 0 total, 1 plastic")
                 .versions(2017)
                 .allow({0, 1})
                 .not_implemented()}),
        card("card 4", {I("fct_IDp", 1, 10, "yield factor as a function of pressure; 0 = none")
                            .refs(IdKind::Other)
                            .not_implemented(),
                        R("Fscale", 11, 30, "pressure scale of fct_IDp").dims(dim::pressure).unused(),
                        I("Fct_IDE", 31, 40, "Young's modulus factor as a function of eps_p; 0 = none")
                            .versions(120)
                            .refs(IdKind::Other)
                            .not_implemented(),
                        R("EInf", 41, 60, "Young's modulus at large eps_p (with CE)")
                            .versions(120)
                            .dims(dim::pressure)
                            .unused(),
                        R("CE", 61, 80, "rate of the Young's modulus change with eps_p; 0 = constant E")
                            .versions(120)
                            .not_implemented()}),
    };
    add_plas_tab_lists(k);
    t.push_back(std::move(k));
  }
  {
    // The keyword line names the material the model is attached to: /FAIL/JOHNSON/mat_ID[/unit_ID].
    KeywordDecl k = kw("/FAIL/JOHNSON", "Johnson-Cook failure model of a material (damage by plastic strain)",
                       Header::IdUnit, false, "mat_ID");
    k.id_kind = IdKind::Material;
    k.cards = {
        card("card 1", {R("D1", 1, 20, "failure strain: constant term"),
                        R("D2", 21, 40, "failure strain: factor of the exponential"),
                        R("D3", 41, 60, "failure strain: factor of the triaxiality in the exponential"),
                        R("D4", 61, 80, "failure strain: factor of ln(rate / rate0)"),
                        R("D5", 81, 100, "failure strain: factor of the temperature term")}),
        card("card 2",
             {R("Epsilon_Dot_0", 1, 20, "reference strain rate; 0 = 1e-20").ge(0.0).dims(dim::rate),
              I("Ifail_sh", 21, 30, "shells: 1 deleted when one point fails, 2 when all fail")
                  .zero_is(1)
                  .allow({0, 1, 2}),
              I("Ifail_so", 31, 40,
                "solids: 1 deleted, 2 deviator zero, 3 deviator zero and no tension, 4 stress zero")
                  .zero_is(1)
                  .allow({0, 1, 2, 3, 4}),
              R("EPSF_MIN", 41, 60, "lower bound of the failure strain").versions(2024).ge(0.0),
              R("Dadv", 61, 80, "damage at which a crack advances (XFEM only)").versions(130).unused(),
              I("Ixfem", 91, 100, "XFEM crack: 0 off, 1 multilayer, 2 monolayer")
                  .versions(120)
                  .allow({0, 1, 2})
                  .not_implemented()}),
        card_v("card 3", 2025, kLastVersion,
               {I("FAILIP", 1, 10, "failed integration points that delete a shell; 0 = 1 (larger: refused)")
                    .ge(0)}),
        card("failure id", {I("fail_ID", 1, 10, "failure model id (optional)").refs(IdKind::Other)}),
    };
    t.push_back(std::move(k));
  }
  {
    // /FAIL/TAB/mat_ID[/unit_ID]: the radioss110 to radioss2018 cfg layouts (OpenRadioss
    // hm_read_fail_tab_old.F; its starter converts the keyword to /FAIL/TAB1 with a /TABLE of the rate
    // lines). Card 1 holds P_thickfail in columns 41-60 from 120 on and in the 90/100 decks (as OpenRadioss's
    // own QA deck of format 100 writes it), in 61-80 in the radioss110 layout.
    KeywordDecl k = kw("/FAIL/TAB", "tabulated failure model of a material (failure strain by triaxiality)",
                       Header::IdUnit, false, "mat_ID");
    k.id_kind = IdKind::Material;
    auto card1 = [](bool v110, bool xfem) {
      std::vector<FieldDecl> f = {
          I("Ifail_sh", 1, 10,
            "shells: 1 one failed point deletes, 2 P_thickfail of the thickness (point "
            "stress zero), 3 the same with the failed points' stress kept")
              .zero_is(1)
              .allow({0, 1, 2, 3}),
          I("Ifail_so", 11, 20, "solids: 1 deleted, 2 normal stresses set to the mean, 3 stress kept")
              .zero_is(1)
              .allow({0, 1, 2, 3}),
          I("N_rate", 21, 30, "number of failure-strain functions (strain rates), 1 to 100")
              .must()
              .gt(0)
              .le(100),
          R("P_thickfail", v110 ? 61 : 41, v110 ? 80 : 60,
            "failed fraction of the thickness that deletes the shell (Ifail_sh 2, 3); 0 = the property's")};
      if (xfem)
        f.push_back(I("Ixfem", 91, 100, "XFEM crack: 0 off, 1 multilayer, 2 monolayer").not_implemented());
      return f;
    };
    k.cards = {
        card_v("card 1", kAnyVersion, 100, card1(false, false)),
        card_v("card 1", 110, 110, card1(true, false)),
        card_v("card 1", 120, kLastVersion, card1(false, true)),
        card("card 2",
             {R("Dcrit", 1, 20, "damage at which the point fails; 0 = 1").zero_is(1.0).gt(0.0),
              R("D", 21, 40, "instability damage of the fading (no fading in /FAIL/TAB); 1 = 0.999").unused(),
              R("n", 41, 60, "damage exponent: dD = n D^(1 - 1/n) d_eps_p / eps_f; 0 = 1")
                  .zero_is(1.0)
                  .gt(0.0),
              R("Dadv", 61, 80, "damage at which a crack advances (XFEM only)").versions(120).unused()}),
    };
    for (int i = 0; i < kFailTabMaxRates; ++i)
      k.cards.push_back(
          card_if(fail_tab_name(3, i), when_gt("N_rate", i),
                  {I(fail_tab_name(0, i), 1, 10, "failure strain eps_f(triaxiality) at this rate")
                       .must()
                       .refs(IdKind::Other),
                   R(fail_tab_name(1, i), 11, 30, "ordinate scale of that function; 0 = 1").zero_is(1.0),
                   R(fail_tab_name(2, i), 31, 50, "strain rate of that function").dims(dim::rate)}));
    k.cards.push_back(
        card("element size",
             {I("fct_IDel", 1, 10, "factor of eps_f by element size / EI_ref; 0 = none").refs(IdKind::Other),
              R("Fscale_el", 11, 30, "scale of that factor; 0 = 1").zero_is(1.0),
              R("EI_ref", 31, 50, "reference element size; 0 = 1").zero_is(1.0).dims(dim::length)}));
    k.cards.push_back(
        card("temperature",
             {I("fct_IDt", 1, 10, "factor of eps_f by temperature; 0 = none (radx: a constant function only)")
                  .refs(IdKind::Other),
              R("FscaleT", 11, 30, "scale of that factor; 0 = 1").zero_is(1.0)}));
    k.cards.push_back(card_v("failure id", 130, kLastVersion,
                             {I("fail_ID", 1, 10, "failure model id (optional)").refs(IdKind::Other)}));
    t.push_back(std::move(k));
  }
  {
    // /FAIL/BIQUAD/mat_ID[/unit_ID]: the radioss2017 to radioss2026 cfg layouts (OpenRadioss
    // hm_read_fail_biquad.F, biquad_coefficients.F). The size function arrives in 2018, the softening card in
    // 2024, FAILIP in 2025, Ireg in 2026.
    KeywordDecl k =
        kw("/FAIL/BIQUAD",
           "biquadratic failure model of a material (failure strain by triaxiality, two parabolas)",
           Header::IdUnit, false, "mat_ID");
    k.id_kind = IdKind::Material;
    k.cards = {
        card("card 1",
             {R("C1", 1, 20, "plastic strain at failure in simple compression (triaxiality -1/3)"),
              R("C2", 21, 40, "plastic strain at failure in shear (triaxiality 0)"),
              R("C3", 41, 60,
                "plastic strain at failure in uniaxial tension (triaxiality 1/3); 0 = the M_Flag "
                "material's"),
              R("C4", 61, 80, "plastic strain at failure in plane strain (triaxiality 1/sqrt(3))"),
              R("C5", 81, 100, "plastic strain at failure in equibiaxial tension (triaxiality 2/3)")}),
        card(
            "card 2",
            {R("P_thickfail", 1, 20,
               "failed fraction of the thickness that deletes the shell, kept in [1e-6, 1]; 0 = 1e-6 "
               "(< 0, a fraction of points: refused)"),
             I("M_Flag", 21, 30,
               "material selector: C1, C2, C4, C5 as multiples of C3: 0 user values (all blank: mild steel), "
               "1 mild steel, 2 HSS, 3 UHSS, 4 AA5182, 5 AA6082-T6, 6 PA6GF30, 7 PP T40, 99 R1 R2 R4 R5"),
             I("S_Flag", 31, 40,
               "above triaxiality 1/3: 1 the second parabola, 2 plane strain the minimum, 3 that and the "
               "shells' necking instability from Inst_start; 0 = 2")
                 .zero_is(2)
                 .allow({0, 1, 2, 3}),
             R("Inst_start", 41, 60,
               "instability strain of S_Flag 3 (at or below 0, or at or above C4: S_Flag 2)"),
             I("Ireg", 61, 70,
               "element size regularisation: 1 the function of the size (2, 3 by triaxiality: "
               "refused); 0 = 1 with a function")
                 .versions(2026),
             I("fct_IDel", 71, 80, "factor of eps_f by element size / EI_ref; 0 = none")
                 .versions(2018)
                 .refs(IdKind::Other),
             R("EI_ref", 81, 100, "reference element size; 0 = 1")
                 .versions(2018)
                 .zero_is(1.0)
                 .dims(dim::length)}),
        card_if("card 3 (M_Flag = 99)", when_eq("M_Flag", 99),
                {R("R1", 1, 20, "C1 / C3 (M_Flag 99)"), R("R2", 21, 40, "C2 / C3 (M_Flag 99)"),
                 R("R4", 41, 60, "C4 / C3 (M_Flag 99)"), R("R5", 61, 80, "C5 / C3 (M_Flag 99)")}),
        card_v("softening", 2024, kLastVersion,
               {I("ICOUP", 11, 20, "stress softening: 0 none (1, 2: refused)"),
                R("DCRIT", 21, 40,
                  "damage at which the softening starts, kept in [0, 1] (> 0: ICOUP 1, refused)"),
                R("EXP", 41, 60, "softening exponent; 0 = 1").zero_is(1.0).unused(),
                I("FAILIP", 61, 70, "failed beam integration points before deletion (beams only)")
                    .versions(2025)
                    .unused()}),
        card("failure id", {I("fail_ID", 1, 10, "failure model id (optional)").refs(IdKind::Other)}),
    };
    t.push_back(std::move(k));
  }
}

// /MAT/PLAS_BRIT (law 27): Johnson-Cook plasticity of shells with a tension crack (OpenRadioss
// hm_read_mat27.F; layouts of the radioss100 and radioss2019 cfg files).
void add_plas_brit(std::vector<KeywordDecl>& t) {
  KeywordDecl k =
      kw("/MAT/LAW27", "brittle elasto-plastic material for shells: Johnson-Cook with a tension crack",
         Header::IdUnit, true, "mat_ID");
  k.aliases = {"/MAT/PLAS_BRIT"};
  k.cards = {
      card("card 1", {R("RHO_I", 1, 20, "initial density").must().gt(0.0).dims(dim::density),
                      R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I").dims(dim::density)}),
      card("card 2", {R("E", 1, 20, "Young's modulus").must().gt(0.0).dims(dim::pressure),
                      R("nu", 21, 40, "Poisson's ratio")}),
      card("card 3", {R("a", 1, 20, "initial yield stress; 0 = 1e20 (no yield)")
                          .zero_is(1e20)
                          .gt(0.0)
                          .dims(dim::pressure),
                      R("b", 21, 40, "hardening modulus").dims(dim::pressure),
                      R("n", 41, 60, "hardening exponent").zero_is(1.0).gt(0.0).le(1.0),
                      R("SIG_max0", 81, 100, "cap on the flow stress").zero_is(1e20).dims(dim::pressure)}),
      card(
          "card 4",
          {R("c", 1, 20, "strain-rate coefficient; 0 = no rate effect"),
           R("EPS_DOT_0", 21, 40, "reference strain rate (needed when c is not 0)").dims(dim::rate),
           I("ICC", 41, 50, "1: the rate term also scales SIG_max0; 2: it does not")
               .zero_is(1)
               .allow({0, 1, 2}),
           I("Fsmooth", 51, 60, "strain rate: 0 the point's strain increment, 1 the element's rate, filtered")
               .versions(2019)
               .allow({0, 1}),
           R("Fcut", 61, 80, "cut-off frequency of the strain-rate filter; not 0 sets Fsmooth 1")
               .versions(2019)
               .ge(0.0)
               .dims(dim::rate)}),
      card("card 5",
           {R("EPS_t1", 1, 20, "principal tensile strain at which the crack opens; 0 = never")
                .zero_is(1e20)
                .gt(0.0),
            R("EPS_m1", 21, 40, "tensile strain at which the damage reaches 1 (slope of the damage)")
                .zero_is(1.1e20)
                .gt(0.0),
            R("d_max1", 41, 60, "largest damage, below 1; 0 = 0.999").zero_is(0.999).ge(0.0).lt(1.0),
            R("EPS_f1", 61, 80, "principal tensile strain at which the element is deleted; 0 = never")
                .zero_is(1.2e22)
                .gt(0.0)}),
      card("card 6",
           {R("EPS_t2", 1, 20, "direction 2: read, never used (OpenRadioss opens only direction 1)").unused(),
            R("EPS_m2", 21, 40, "direction 2: read, never used").unused(),
            R("d_max2", 41, 60, "direction 2: read, never used").unused(),
            R("EPS_f2", 61, 80, "direction 2: read, never used").unused()}),
  };
  t.push_back(std::move(k));
}

// ---------------------------------------------------------------------------------------------------------
// Groups and surfaces
void add_groups(std::vector<KeywordDecl>& t) {
  // The kind of the listed ids follows the keyword's last word: nodes, elements, parts, materials,
  // properties; groups, boxes, subsets and surfaces take the default offset.
  auto listed = [](std::string_view path) {
    const auto word = path.substr(path.find('/', 1) + 1);
    if (word == "NODE" || word == "GENE") return IdKind::Node;
    if (word == "SHEL" || word == "SH3N" || word == "BRIC" || word == "TRUS" || word == "BEAM")
      return IdKind::Element;
    if (word.substr(0, 4) == "PART") return IdKind::Part;
    if (word == "MAT") return IdKind::Material;
    if (word == "PROP") return IdKind::Property;
    return IdKind::Other;
  };
  auto id_group = [&t, &listed](std::string_view path, std::string_view meaning, std::string_view id_name) {
    KeywordDecl k = kw(path, meaning, Header::Id, true, id_name);
    k.tail = Tail::IdList;
    k.list_kind = listed(path);
    t.push_back(std::move(k));
  };
  id_group("/GRNOD/NODE", "node group: the listed node ids", "grnod_ID");
  id_group("/GRNOD/PART", "node group: the nodes of the listed parts' elements; a negative id removes",
           "grnod_ID");
  id_group("/GRNOD/GRNOD", "node group: union of node groups; a negative id removes", "grnod_ID");
  id_group("/GRNOD/BOX", "node group: the nodes inside the listed boxes", "grnod_ID");
  id_group("/GRNOD/SUBSET", "node group: the nodes of the parts of the listed subsets (and their children)",
           "grnod_ID");
  id_group("/GRNOD/MAT", "node group: the nodes of the elements of the parts with the listed materials",
           "grnod_ID");
  id_group("/GRNOD/PROP", "node group: the nodes of the elements of the parts with the listed properties",
           "grnod_ID");
  id_group("/GRNOD/SURF", "node group: the nodes of the listed surfaces' segments", "grnod_ID");
  id_group("/GRNOD/GENE", "node group: existing node ids in ranges given as pairs (first, last)", "grnod_ID");
  {
    // Declared from 2017: the 2017/2018 layouts lack it, and a deck of those versions that uses it reads the
    // same way. How the older readers (which do not know it) would take its lines is not established.
    KeywordDecl k = kw("/GRNOD/GEN_INCR", "node group: arithmetic node id ranges, one per line", Header::Id,
                       true, "grnod_ID");
    k.since = 2017;
    k.tail = Tail::Records;
    k.record = card("range", {I("first", 1, 10, "first node id of the range").refs(IdKind::Node),
                              I("last", 11, 20, "last node id of the range").refs(IdKind::Node),
                              I("incr", 21, 30, "step between node ids")});
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/BOX/RECTA", "axis-aligned box given by two opposite corners", Header::IdUnit, true, "box_ID");
    k.cards = {
        card("card 1",
             {I("N1", 1, 10, "node giving the first corner (with N2: both nodes replace Xp1 ... Zp2)")
                  .refs(IdKind::Node),
              I("N2", 11, 20, "node giving the second corner (with N1)").refs(IdKind::Node),
              I("Iskew", 21, 30, "skew the box is aligned with; 0 = global axes").refs(IdKind::Other)}),
        card("card 2", {R("Xp1", 1, 20, "first corner X").dims(dim::length),
                        R("Yp1", 21, 40, "first corner Y").dims(dim::length),
                        R("Zp1", 41, 60, "first corner Z").dims(dim::length)}),
        card("card 3", {R("Xp2", 1, 20, "second corner X").dims(dim::length),
                        R("Yp2", 21, 40, "second corner Y").dims(dim::length),
                        R("Zp2", 41, 60, "second corner Z").dims(dim::length)}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/BOX/CYLIN",
           "finite cylinder box: the axis from P1 to P2 (the centres of its end faces) and a diameter",
           Header::IdUnit, true, "box_ID");
    k.cards = {
        card("card 1",
             {I("N1", 1, 10, "node giving P1 (with N2: both nodes replace Xp1 ... Zp2)").refs(IdKind::Node),
              I("N2", 11, 20, "node giving P2 (with N1)").refs(IdKind::Node),
              R("Diameter", 31, 50, "diameter of the cylinder").dims(dim::length).must().gt(0.0)}),
        card("card 2", {R("Xp1", 1, 20, "centre P1 of the first end face, X").dims(dim::length),
                        R("Yp1", 21, 40, "centre P1, Y").dims(dim::length),
                        R("Zp1", 41, 60, "centre P1, Z").dims(dim::length)}),
        card("card 3", {R("Xp2", 1, 20, "centre P2 of the second end face, X").dims(dim::length),
                        R("Yp2", 21, 40, "centre P2, Y").dims(dim::length),
                        R("Zp2", 41, 60, "centre P2, Z").dims(dim::length)}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/BOX/SPHER", "sphere box: a centre and a diameter", Header::IdUnit, true, "box_ID");
    k.cards = {
        card("card 1", {I("N1", 1, 10, "node giving the centre (replaces Xp1 Yp1 Zp1)").refs(IdKind::Node),
                        R("Diameter", 31, 50, "diameter of the sphere").dims(dim::length).must().gt(0.0)}),
        card("card 2",
             {R("Xp1", 1, 20, "centre X").dims(dim::length), R("Yp1", 21, 40, "centre Y").dims(dim::length),
              R("Zp1", 41, 60, "centre Z").dims(dim::length)}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/SUBSET", "subset of parts: lists its child subsets", Header::OptionalId, true, "subset_ID");
    k.tail = Tail::IdList;
    k.list_kind = IdKind::Other;
    t.push_back(std::move(k));
  }
  // Element groups. Each family has its own ids; the keyword line may carry a unit id, as Radioss reads one
  // (it only matters to Radioss for boxes, and radx's boxes are already in work units).
  auto element_group = [&t, &listed](std::string_view path, std::string_view meaning,
                                     std::string_view id_name) {
    KeywordDecl k = kw(path, meaning, Header::IdUnit, true, id_name);
    k.tail = Tail::IdList;
    k.list_kind = listed(path);
    t.push_back(std::move(k));
  };
  element_group("/GRSHEL/SHEL", "4-node shell group: the listed /SHELL element ids", "grshel_ID");
  element_group("/GRSHEL/PART", "4-node shell group: the shells of the listed parts; a negative id removes",
                "grshel_ID");
  element_group("/GRSHEL/GRSHEL", "4-node shell group: union of /GRSHEL groups; a negative id removes",
                "grshel_ID");
  element_group("/GRSHEL/SUBSET",
                "4-node shell group: the shells of the parts of the listed subsets (and their children); a "
                "negative id removes",
                "grshel_ID");
  element_group(
      "/GRSHEL/MAT",
      "4-node shell group: the shells of the parts with the listed materials; a negative id removes",
      "grshel_ID");
  element_group(
      "/GRSHEL/PROP",
      "4-node shell group: the shells of the parts with the listed properties; a negative id removes",
      "grshel_ID");
  element_group(
      "/GRSHEL/BOX",
      "4-node shell group: the shells whose nodes all lie in the box (only the first box id counts)",
      "grshel_ID");
  element_group(
      "/GRSHEL/BOX2",
      "4-node shell group: the shells with at least one node in the box (only the first box id counts)",
      "grshel_ID");
  // GENE: pairs (first, last) of element ids, the ids of each range that exist (the last word is not a
  // node list here).
  auto element_gene = [&t, &element_group](std::string_view path, std::string_view meaning,
                                           std::string_view id_name) {
    element_group(path, meaning, id_name);
    t.back().list_kind = IdKind::Element;
  };
  element_gene("/GRSHEL/GENE",
               "4-node shell group: the existing /SHELL ids in ranges given as pairs (first, last)",
               "grshel_ID");
  element_group("/GRSH3N/SH3N", "3-node shell group: the listed /SH3N element ids", "grsh3n_ID");
  element_group("/GRSH3N/PART",
                "3-node shell group: the 3-node shells of the listed parts; a negative id removes",
                "grsh3n_ID");
  element_group("/GRSH3N/GRSH3N", "3-node shell group: union of /GRSH3N groups; a negative id removes",
                "grsh3n_ID");
  element_group(
      "/GRSH3N/SUBSET",
      "3-node shell group: the 3-node shells of the parts of the listed subsets (and their children); "
      "a negative id removes",
      "grsh3n_ID");
  element_group("/GRSH3N/MAT",
                "3-node shell group: the 3-node shells of the parts with the listed materials; a negative id "
                "removes",
                "grsh3n_ID");
  element_group(
      "/GRSH3N/PROP",
      "3-node shell group: the 3-node shells of the parts with the listed properties; a negative id "
      "removes",
      "grsh3n_ID");
  element_group("/GRSH3N/BOX",
                "3-node shell group: the 3-node shells whose nodes all lie in the box (only the first box id "
                "counts)",
                "grsh3n_ID");
  element_group(
      "/GRSH3N/BOX2",
      "3-node shell group: the 3-node shells with at least one node in the box (only the first box id "
      "counts)",
      "grsh3n_ID");
  element_gene("/GRSH3N/GENE",
               "3-node shell group: the existing /SH3N ids in ranges given as pairs (first, last)",
               "grsh3n_ID");
  element_group("/GRBRIC/BRIC", "brick group: the listed /BRICK, /TETRA4 and /BRIC20 element ids",
                "grbric_ID");
  element_gene(
      "/GRBRIC/GENE",
      "brick group: the existing /BRICK, /TETRA4 and /BRIC20 ids in ranges given as pairs (first, last)",
      "grbric_ID");
  element_group(
      "/GRBRIC/PART",
      "brick group: the bricks, tetrahedra and 20-node bricks of the listed parts; a negative id removes",
      "grbric_ID");
  element_group("/GRBRIC/GRBRIC", "brick group: union of /GRBRIC groups; a negative id removes", "grbric_ID");
  element_group(
      "/GRBRIC/SUBSET",
      "brick group: the bricks of the parts of the listed subsets (and their children); a negative id "
      "removes",
      "grbric_ID");
  element_group("/GRBRIC/MAT",
                "brick group: the bricks of the parts with the listed materials; a negative id removes",
                "grbric_ID");
  element_group("/GRBRIC/PROP",
                "brick group: the bricks of the parts with the listed properties; a negative id removes",
                "grbric_ID");
  element_group("/GRBRIC/BOX",
                "brick group: the bricks, tetrahedra and 20-node bricks whose nodes all lie in the box (only "
                "the first box id counts)",
                "grbric_ID");
  element_group("/GRBRIC/BOX2",
                "brick group: the bricks, tetrahedra and 20-node bricks with at least one node in the box "
                "(only the first "
                "box id counts)",
                "grbric_ID");
  // Sets (/SET/GENERAL, /SET/COLLECT): clause lines, each a clause word then ids. The ids' kind depends on
  // the clause (nodes, parts, elements, boxes, sets), so a set inside a //SUBMODEL is refused by the builder
  // rather than shifted by one offset.
  for (const auto& [path, meaning] :
       {std::pair{
            std::string_view("/SET/GENERAL"),
            std::string_view("set: nodes, parts, elements and a surface from clauses combined in order, "
                             "usable wherever a node group, an element group or a surface is named")},
        std::pair{std::string_view("/SET/COLLECT"),
                  std::string_view(
                      "set like /SET/GENERAL; every /SET/COLLECT with the same id adds to one set")}}) {
    KeywordDecl k = kw(path, meaning, Header::Id, true, "set_ID");
    k.tail = Tail::Clauses;
    k.record =
        card("clause", {S("clause", 1, 10,
                          "PART, NODE, SHELL, SH3N, SOLID, SET, SETCOL, BOX, BOX2 or ALL, with options "
                          "after '_': D removes, G generates (first last step), I intersects (SET), O "
                          "flips shell normals, A takes every solid face; blank: the clause above goes on")});
    for (const auto name :
         {"item1", "item2", "item3", "item4", "item5", "item6", "item7", "item8", "item9"}) {
      const int c = 11 + 10 * static_cast<int>(name[4] - '1');
      k.record.fields.push_back(
          I(name, c, c + 9, "an id of the clause's kind (or first, last, step with _G)"));
    }
    k.text_meaning =
        "Clauses are applied in order: a plain clause adds, _D removes, _I keeps what both hold; each kind "
        "of "
        "member (nodes, parts, shells, 3-node shells, solids, surface segments) separately (docs/sets.md).";
    t.push_back(std::move(k));
  }
  // Truss and beam groups: the same subtypes as the shells' (BOX: the element's two nodes, not a beam's
  // orientation node).
  element_group("/GRTRUS/TRUS", "truss group: the listed /TRUSS element ids", "grtrus_ID");
  element_group("/GRTRUS/PART", "truss group: the elements of the listed parts; a negative id removes",
                "grtrus_ID");
  element_group("/GRTRUS/GRTRUS", "truss group: union of /GRTRUS groups; a negative id removes", "grtrus_ID");
  element_group("/GRTRUS/SUBSET",
                "truss group: the elements of the parts of the listed subsets (and their children); a "
                "negative id removes",
                "grtrus_ID");
  element_group("/GRTRUS/MAT",
                "truss group: the elements of the parts with the listed materials; a negative id removes",
                "grtrus_ID");
  element_group("/GRTRUS/PROP",
                "truss group: the elements of the parts with the listed properties; a negative id removes",
                "grtrus_ID");
  element_group("/GRTRUS/BOX",
                "truss group: the elements whose two nodes lie in the box (only the first box id counts)",
                "grtrus_ID");
  element_group("/GRTRUS/BOX2",
                "truss group: the elements with at least one node in the box (only the first box id counts)",
                "grtrus_ID");
  element_gene("/GRTRUS/GENE", "truss group: the existing /TRUSS ids in ranges given as pairs (first, last)",
               "grtrus_ID");
  element_group("/GRBEAM/BEAM", "beam group: the listed /BEAM element ids", "grbeam_ID");
  element_group("/GRBEAM/PART", "beam group: the elements of the listed parts; a negative id removes",
                "grbeam_ID");
  element_group("/GRBEAM/GRBEAM", "beam group: union of /GRBEAM groups; a negative id removes", "grbeam_ID");
  element_group("/GRBEAM/SUBSET",
                "beam group: the elements of the parts of the listed subsets (and their children); a "
                "negative id removes",
                "grbeam_ID");
  element_group("/GRBEAM/MAT",
                "beam group: the elements of the parts with the listed materials; a negative id removes",
                "grbeam_ID");
  element_group("/GRBEAM/PROP",
                "beam group: the elements of the parts with the listed properties; a negative id removes",
                "grbeam_ID");
  element_group("/GRBEAM/BOX",
                "beam group: the elements whose two nodes lie in the box (only the first box id counts)",
                "grbeam_ID");
  element_group("/GRBEAM/BOX2",
                "beam group: the elements with at least one node in the box (only the first box id counts)",
                "grbeam_ID");
  element_gene("/GRBEAM/GENE", "beam group: the existing /BEAM ids in ranges given as pairs (first, last)",
               "grbeam_ID");
  id_group("/GRNOD/GRSHEL", "node group: the nodes of the shells of the listed /GRSHEL groups", "grnod_ID");
  id_group("/GRNOD/GRSH3N", "node group: the nodes of the 3-node shells of the listed /GRSH3N groups",
           "grnod_ID");
  id_group("/GRNOD/GRBRIC", "node group: the nodes of the bricks of the listed /GRBRIC groups", "grnod_ID");
  id_group("/GRNOD/GRTRUS", "node group: the nodes of the trusses of the listed /GRTRUS groups", "grnod_ID");
  id_group("/GRNOD/GRBEAM", "node group: the two nodes of the beams of the listed /GRBEAM groups",
           "grnod_ID");
  id_group("/SURF/PART", "surface: the shell and 3-node shell segments of the listed parts", "surf_ID");
  id_group("/SURF/PART/EXT", "surface: shell segments and outer solid faces of the listed parts", "surf_ID");
  id_group("/SURF/PART/ALL",
           "surface: shell segments and every face of the solids of the listed parts, inner faces included "
           "(once from each side)",
           "surf_ID");
  id_group("/SURF/GRSHEL",
           "surface: the shells of the listed /GRSHEL groups, oriented as the elements; a negative id flips",
           "surf_ID");
  id_group("/SURF/GRSH3N",
           "surface: the 3-node shells of the listed /GRSH3N groups, oriented as the elements; a negative id "
           "flips",
           "surf_ID");
  id_group("/SURF/GRBRIC/EXT",
           "surface: the faces of the groups' bricks that no other brick of the groups shares, pointing out",
           "surf_ID");
  id_group("/SURF/GRBRIC/FREE",
           "surface: the faces of the groups' bricks that no other brick of the model shares, pointing out",
           "surf_ID");
  id_group("/SURF/GRBRIC",
           "refused, as Radioss refuses it: a brick group makes a surface only as /SURF/GRBRIC/EXT or /FREE",
           "surf_ID");
  {
    KeywordDecl k = kw("/SURF/SEG", "surface: explicit segments, one per line", Header::Id, true, "surf_ID");
    k.tail = Tail::Records;
    k.record = card("segment",
                    {I("seg_ID", 1, 10, "segment id"),
                     I("n1", 11, 20, "first node; the normal follows n1, n2, n3").refs(IdKind::Node).must(),
                     I("n2", 21, 30, "second node").refs(IdKind::Node).must(),
                     I("n3", 31, 40, "third node").refs(IdKind::Node).must(),
                     I("n4", 41, 50, "fourth node; 0 makes a triangle").refs(IdKind::Node)});
    t.push_back(std::move(k));
  }
}

// ---------------------------------------------------------------------------------------------------------
// Contact
std::vector<FieldDecl> type7_friction_c1_c5() {
  return {R("C1", 1, 20, "friction law coefficient 1"), R("C2", 21, 40, "friction law coefficient 2"),
          R("C3", 41, 60, "friction law coefficient 3"), R("C4", 61, 80, "friction law coefficient 4"),
          R("C5", 81, 100, "friction law coefficient 5")};
}

std::vector<FieldDecl> type7_adaptive_meshing() {
  return {I("NRadm", 1, 10, "elements through a 90 degree radius").unused(),
          R("Padm", 11, 30, "penetration percentage criterion").unused(),
          R("Angladm", 31, 50, "angle criterion (degrees)").unused()};
}

FieldDecl ibc(std::string_view name, int col, std::string_view meaning) {
  return I(name, col, col, meaning).allow({0, 1});
}

// /INTER/TYPE7 and /INTER/LAGDT/TYPE7 read the same cards, declared once here. The LAGDT layout has none of
// TYPE7's thermal, curvature (TYPE7's card 4) and adaptive-meshing options, nor the fields the later TYPE7
// layouts added (Fpenmax, mesh_size, dtmin, Irem_gap, Irem_i2, Itied, Ists, sens_ID, fct_IDF, AscaleF,
// fric_ID); it keeps Multimp up to 130 where TYPE7 drops it after 110, and numbers its cards without TYPE7's
// card 4.
enum class Type7Layout : std::uint8_t { Type7, LagdtType7 };

void add_type7_cards(KeywordDecl& k, Type7Layout layout) {
  const bool type7 = layout == Type7Layout::Type7;
  // Appends fields that only /INTER/TYPE7 has.
  const auto type7_only = [type7](std::vector<FieldDecl>& fields, std::initializer_list<FieldDecl> more) {
    if (type7) fields.insert(fields.end(), more);
  };

  std::vector<FieldDecl> card1 = {I("grnd_IDs", 1, 10, "secondary node group").refs(IdKind::Other),
                                  I("surf_IDm", 11, 20, "main surface").refs(IdKind::Other).must(),
                                  I("Istf", 21, 30, "stiffness definition").allow({0, 1, 2, 3, 4, 5})};
  type7_only(card1, {I("Ithe", 31, 40, "heat transfer through the contact").allow({0, 1}).unused()});
  card1.insert(
      card1.end(),
      {I("Igap", 41, 50, "gap option: 0 constant, 1 variable, 2 variable with scale and cap")
           .allow({0, 1, 2, 1000}),
       multimp().versions(kAnyVersion, type7 ? 110 : 130),
       I("Ibag", 61, 70, "airbag vent-hole closure on contact").allow({0, 1}).unused(),
       I("Idel", 71, 80, "removal of deleted segments and free secondary nodes").allow({-2, -1, 0, 1, 2})});
  type7_only(card1, {I("Icurv", 81, 90, "curved gap envelope").not_implemented(),
                     I("Iadm", 91, 100, "local curvature for adaptive meshing").unused()});

  std::vector<FieldDecl> card2 = {
      R("Fscalegap", 1, 20, "gap scale factor (Igap = 2)").zero_is(1.0).gt(0.0),
      R("Gapmax", 21, 40, "largest gap (Igap = 2); 0 = no cap").ge(0.0).dims(dim::length)};
  type7_only(card2,
             {R("Fpenmax", 41, 60, "initial penetrations above this fraction of the gap are deactivated")
                  .versions(120)
                  .ge(0.0),
              I("Itied", 81, 90, "tie nodes once in contact").versions(2020).not_implemented(),
              I("Ists", 91, 100, "surface-to-surface option").versions(2026).not_implemented()});

  std::vector<FieldDecl> card3 = {
      R("Stmin", 1, 20, "smallest pair stiffness (Istf 2..5)").ge(0.0).dims(dim::stiffness),
      R("Stmax", 21, 40, "largest pair stiffness (Istf 2..5)").zero_is(1e30).ge(0.0).dims(dim::stiffness)};
  type7_only(card3, {R("mesh_size", 41, 60, "percentage of mesh size for the self-contact gap")
                         .versions(110)
                         .not_implemented(),
                     R("dtmin", 61, 80, "interface minimum time step: a node below it is removed")
                         .versions(120)
                         .ge(0.0)
                         .dims(dim::time),
                     I("Irem_gap", 81, 90, "deactivate secondary nodes when element size is below the gap")
                         .versions(120)
                         .not_implemented(),
                     I("Irem_i2", 91, 100, "deactivate secondary nodes also tied by a TYPE2 interface")
                         .versions(130)
                         .unused()});

  std::vector<FieldDecl> friction = {
      I("Ifric", 1, 10, "friction law: 0 Coulomb, 1 viscous, 2 Darmstad, 3 Renard").allow({0, 1, 2, 3}),
      I("Ifiltr", 11, 20, "friction force filter").allow({0, 1, 2, 3}),
      R("Xfreq", 21, 40, "filter coefficient (a frequency for Ifiltr = 3)").ge(0.0),
      I("Iform", 41, 50, "friction penalty: 1 viscous (total), 2 stiffness (incremental)")
          .zero_is(1)
          .allow({0, 1, 2})};
  type7_only(
      friction,
      {I("sens_ID", 51, 60,
         "sensor that switches the interface on (and off again at the sensor's Tstop); 0 = none")
           .refs(IdKind::Other)
           .versions(120),
       I("fct_IDF", 61, 70, "function scaling friction with temperature")
           .refs(IdKind::Other)
           .versions(140)
           .not_implemented(),
       R("AscaleF", 71, 90, "abscissa scale of fct_IDF").versions(140).unused(),
       I("fric_ID", 91, 100, "/FRICTION definition").refs(IdKind::Other).versions(2018).not_implemented()});

  k.cards = {card("card 1", std::move(card1)), card("card 2", std::move(card2)),
             card("card 3", std::move(card3))};
  if (type7)
    k.cards.push_back(card_if(
        "card 4 (Icurv = 1 or 2)", when_in("Icurv", 1, 2),
        {I("node_ID1", 1, 10, "first node defining the curvature").refs(IdKind::Node).not_implemented(),
         I("node_ID2", 11, 20, "second node defining the curvature").refs(IdKind::Node).not_implemented()}));
  k.cards.push_back(
      card(type7 ? "card 5" : "card 4",
           {R("Stfac", 1, 20, "stiffness scale factor, or the stiffness itself when Istf = 1")
                .zero_is(1.0)
                .gt(0.0),
            R("Fric", 21, 40, "Coulomb friction coefficient").ge(0.0),
            R("Gapmin", 41, 60, "smallest gap; the constant gap when Igap = 0").ge(0.0).dims(dim::length),
            R("Tstart", 61, 80, "time the interface starts acting").dims(dim::time),
            R("Tstop", 81, 100, "time the interface stops acting; 0 = never").dims(dim::time)}));
  k.cards.push_back(
      card(type7 ? "card 6" : "card 5",
           {ibc("IBCX", 8, "release the secondary node's fixed X translation at first impact"),
            ibc("IBCY", 9, "release the secondary node's fixed Y translation at first impact"),
            ibc("IBCZ", 10, "release the secondary node's fixed Z translation at first impact"),
            I("Inacti", 31, 40, "treatment of initial penetrations").allow({0, 1, 2, 3, 5, 6}),
            R("VISs", 41, 60, "critical damping ratio on the normal stiffness").zero_is(0.05).ge(0.0),
            R("VISF", 61, 80, "critical damping ratio on friction").zero_is(1.0).ge(0.0),
            R("Bumult", 81, 100, "sorting margin factor; 0 = default by model size").ge(0.0)}));
  k.cards.push_back(card(type7 ? "card 7" : "card 6", std::move(friction)));
  k.cards.push_back(card_if("friction C1..C5 (Ifric > 0)", when_gt("Ifric", 0), type7_friction_c1_c5()));
  k.cards.push_back(card_if("friction C6 (Ifric > 1)", when_gt("Ifric", 1),
                            {R("C6", 1, 20, "friction law coefficient 6")}));
  if (type7) {
    // From 110 the adaptive-meshing card comes before the thermal cards; up to 100 after them.
    k.cards.push_back(card_v_if("adaptive meshing (Iadm = 2)", 110, kLastVersion, when_eq("Iadm", 2),
                                type7_adaptive_meshing()));
    k.cards.push_back(
        card_v_if("thermal 1 (Ithe = 1)", 100, kLastVersion, when_eq("Ithe", 1),
                  {R("Kthe", 1, 20, "heat exchange coefficient").dims(kHeatTransfer).unused(),
                   I("fct_IDK", 21, 30, "function of the heat exchange coefficient versus pressure")
                       .refs(IdKind::Other)
                       .versions(140)
                       .unused(),
                   R("Tint", 41, 60, "interface temperature (kelvin)").unused(),
                   I("Ithe_form", 61, 70, "heat contact formulation").unused(),
                   R("AscaleK", 71, 90, "abscissa (pressure) scale of fct_IDK")
                       .versions(140)
                       .dims(dim::pressure)
                       .unused()}));
    k.cards.push_back(
        card_v_if("thermal 2 (Ithe = 1)", 140, kLastVersion, when_eq("Ithe", 1),
                  {R("Frad", 1, 20, "radiation factor").dims(kHeatTransfer).unused(),
                   R("Drad", 21, 40, "largest distance for radiation").dims(dim::length).unused(),
                   R("Fheats", 41, 60, "share of frictional heat given to the secondary side").unused(),
                   R("Fheatm", 61, 80, "share of frictional heat given to the main side").unused()}));
    // The 90 layout reads its thermal card for Ithe > 1 (a value radx does not accept).
    k.cards.push_back(card_v_if("thermal (Ithe > 1)", kAnyVersion, 90, when_gt("Ithe", 1),
                                {R("Kthe", 1, 20, "heat exchange coefficient").dims(kHeatTransfer).unused(),
                                 R("Tint", 41, 60, "interface temperature (kelvin)").unused()}));
    k.cards.push_back(card_v_if("adaptive meshing (Iadm = 2)", kAnyVersion, 100, when_eq("Iadm", 2),
                                type7_adaptive_meshing()));
  }
  k.dim_overrides = {{"Stfac", "Istf", {"1"}, dim::stiffness}, {"Xfreq", "Ifiltr", {"3"}, dim::rate}};
}

void add_contact(std::vector<KeywordDecl>& t) {
  {
    KeywordDecl k =
        kw("/INTER/TYPE7", "node-to-surface penalty contact with a gap", Header::IdUnit, true, "inter_ID");
    add_type7_cards(k, Type7Layout::Type7);
    t.push_back(std::move(k));
  }
  {
    // The Spotflag values OpenRadioss reads (hm_read_inter_type02.F); radx runs 0, 5 and 1 and refuses the
    // others by name (parser/building/build_tied.cpp).
    KeywordDecl k =
        kw("/INTER/TYPE2", "tied interface: secondary nodes move with the main segments they sit on",
           Header::IdUnit, true, "inter_ID");
    k.cards = {
        card("card 1",
             {I("grnd_IDs", 1, 10, "secondary node group").refs(IdKind::Other).must(),
              I("surf_IDm", 11, 20, "main surface").refs(IdKind::Other).must(),
              I("Ignore", 21, 30,
                "secondary nodes without a main segment: 0 error, 1 (2, 3 with Dsearch > 0) removed with a "
                "warning")
                  .versions(110)
                  .allow({0, 1, 2, 3, 1000}),
              I("Spotflag", 31, 40,
                "formulation: 0 or 5 standard kinematic tie, 1 rigid tie (the node moves with the segment's "
                "least-squares rotation; others refused by name)")
                  .allow({0, 1, 2, 3, 4, 5, 10, 11, 12, 20, 21, 22, 25, 26, 27, 28, 30}),
              I("Level", 41, 50, "hierarchy level of the kinematic condition").unused(),
              I("Isearch", 51, 60, "search algorithm").allow({0, 1, 2}).unused(),
              I("Idel2", 61, 70, "release the tie when the main elements are deleted").allow({0, 1, 2, 1000}),
              R("Dsearch", 81, 100, "search distance; 0 = the mean main segment edge length")
                  .ge(0.0)
                  .dims(dim::length)}),
        card_if("rupture 1 (Spotflag 20..22)", when_in("Spotflag", 20, 22),
                {I("Rupt", 1, 10, "rupture model").unused(), I("Ifiltr", 11, 20, "filter").unused(),
                 I("fct_IDsr", 21, 30, "stress factor versus stress rate").refs(IdKind::Other).unused(),
                 I("fct_IDsn", 31, 40, "normal stress versus displacement").refs(IdKind::Other).unused(),
                 I("fct_IDst", 41, 50, "tangential stress versus displacement").refs(IdKind::Other).unused(),
                 I("Isym", 51, 60, "symmetry").unused(), R("Max_N_Dist", 61, 80, "").unused(),
                 R("Max_T_Dist", 81, 100, "").unused()}),
        card_if("rupture 2 (Spotflag 20..22)", when_in("Spotflag", 20, 22),
                {R("Fscalestress", 1, 20, "").unused(), R("Fscalestr_rate", 21, 40, "").unused(),
                 R("Fscaledist", 41, 60, "").unused(), R("Alpha", 61, 80, "").unused(),
                 R("Area", 81, 100, "").versions(140).unused()}),
        card_if("penalty (Spotflag 25, 26)", when_in("Spotflag", 25, 26),
                {R("Stfac", 1, 20, "penalty stiffness factor").unused(),
                 R("Visc", 21, 40, "critical damping factor").unused(),
                 I("Istf", 61, 70, "penalty stiffness definition").versions(140).unused()}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/INTER/LAGDT/TYPE7",
                       "TYPE7 contact whose pairs switch to Lagrange multipliers below the minimum time step",
                       Header::IdUnit, true, "inter_ID");
    add_type7_cards(k, Type7Layout::LagdtType7);
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/CTCLAW", "contact and friction law (URN string) attached to one interface",
                       Header::Id, true, "law_ID");
    k.cards = {card("card 1", {I("inter_ID", 1, 10, "interface (TYPE7 or LAGDT/TYPE7) that uses the law")
                                   .refs(IdKind::Other)
                                   .must()})};
    k.tail = Tail::Text;
    k.text_meaning =
        "The law string (`docs/theory/contact-laws.md`): "
        "`n<normal>s<friction>{Name1Value1,Name2Value2,...}`, "
        "e.g. `n2s13{pz1e5,lambda2e3,KcMax1e15,Mu0.3,CtLin10}`. Names are case-insensitive; a value follows "
        "its "
        "name directly (`Mu.1`) or after `=`; numbers in C or Fortran form (`1e5`, `1.D5`, `.5`, `-1`); "
        "values "
        "in the deck's input units.\n\n"
        "- Normal law (leave `n` out to keep the interface's own penalty): `n1` bilinear P = Kc u, `Kc` > 0 "
        "or "
        "-1 (automatic: K / A_s, K the pair stiffness, A_s the tributary area of the secondary node); `n2` "
        "exponential P = pz exp(lambda u), `pz` > 0 and one of `lambda` > 0 or `pe` > 0 (the expected "
        "working "
        "pressure: lambda = (K / A_s) / pe), `KcMax` > 0 optional (the stiffness bound, beyond which the law "
        "goes on linearly; not below the initial stiffness lambda pz); `n3` tabulated, `CurveID` the "
        "`/FUNCT` "
        "of gap to pressure (at least 2 points, pressures >= 0 that do not rise with the gap), `Cubic` 0 "
        "(linear, default) or 1 (monotone cubic); `n4` power P = sum of kp_m u^m, one or more "
        "`kp<m>=<value>` "
        "(m >= 1, each once; values >= 0, one > 0).\n"
        "- Friction law (leave `s` out for no friction): `s1` exact Coulomb, `s2` linear min(ct s, mu p), "
        "`s3` "
        "arctangent mu p (2/pi) atan(ct s), `s4` scaled linear p min(ct s, mu), sliding along the segment's "
        "first tangent; `s11` to `s14` the same in the whole tangent plane. `Mu` >= 0 for all, `CtLin` > 0 "
        "for s2 to s4 and s12 to s14 (not s1, s11), `kappa` > 0 optional (the sticking stiffness per unit "
        "area; "
        "default K / A_s).\n"
        "- An unknown law or parameter, a parameter the law does not take, a repeated, missing, non-numeric "
        "or "
        "out-of-range one, lambda with pe, KcMax below the initial stiffness (with pe: over the secondary "
        "nodes), a missing or rising curve, unbalanced braces: RX704, at the law string's line.";
    t.push_back(std::move(k));
  }
}

// ---------------------------------------------------------------------------------------------------------
// Boundary conditions, initial conditions, loads, functions
void add_loads(std::vector<KeywordDecl>& t) {
  {
    KeywordDecl k =
        kw("/BCS", "fixed translations and rotations of a node group", Header::Id, true, "bcs_ID");
    k.cards = {card(
        "card 1", {I("Tx", 4, 4, "1 = X translation fixed").allow({0, 1}),
                   I("Ty", 5, 5, "1 = Y translation fixed").allow({0, 1}),
                   I("Tz", 6, 6, "1 = Z translation fixed").allow({0, 1}),
                   I("Rx", 8, 8, "1 = X rotation fixed").allow({0, 1}),
                   I("Ry", 9, 9, "1 = Y rotation fixed").allow({0, 1}),
                   I("Rz", 10, 10, "1 = Z rotation fixed").allow({0, 1}),
                   I("skew_ID", 11, 20, "skew of the fixed directions; 0 = global axes").refs(IdKind::Other),
                   I("grnod_ID", 21, 30, "nodes concerned").refs(IdKind::Other)})};
    t.push_back(std::move(k));
  }
  {
    // OpenRadioss hm_read_alebcs.F: the same card as /BCS, its six codes the grid velocity (3) and the
    // material velocity (3) of ALE nodes.
    KeywordDecl k =
        kw("/ALE/BCS",
           "ALE boundary condition: fixed grid and material velocities of ALE nodes (no effect on the "
           "Lagrangian nodes radx runs)",
           Header::Id, true, "bcs_ID");
    k.cards = {card(
        "card 1", {I("Gx", 4, 4, "1 = grid velocity X fixed").allow({0, 1}),
                   I("Gy", 5, 5, "1 = grid velocity Y fixed").allow({0, 1}),
                   I("Gz", 6, 6, "1 = grid velocity Z fixed").allow({0, 1}),
                   I("Mx", 8, 8, "1 = material velocity X fixed").allow({0, 1}),
                   I("My", 9, 9, "1 = material velocity Y fixed").allow({0, 1}),
                   I("Mz", 10, 10, "1 = material velocity Z fixed").allow({0, 1}),
                   I("skew_ID", 11, 20, "skew of the fixed directions; 0 = global axes").refs(IdKind::Other),
                   I("grnod_ID", 21, 30, "nodes concerned").refs(IdKind::Other)})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/IMPVEL", "imposed velocity on a node group, following a function of time",
                       Header::IdUnit, true, "impvel_ID");
    k.cards = {
        card("card 1",
             {I("funct_IDT", 1, 10, "velocity versus time function").refs(IdKind::Other).must(),
              S("Dir", 11, 20, "direction: X, Y, Z (translation) or XX, YY, ZZ (rotation)"),
              I("skew_ID", 21, 30, "skew of the direction; 0 = global axes").refs(IdKind::Other),
              I("sensor_ID", 31, 40, "sensor that starts the velocity; 0 = none").refs(IdKind::Other),
              I("grnod_ID", 41, 50, "nodes concerned").refs(IdKind::Other),
              I("frame_ID", 51, 60, "moving frame of the direction (exclusive with skew); 0 = none")
                  .refs(IdKind::Other),
              I("Icoor", 61, 70, "0 Cartesian, 1 cylindrical (with a frame)").versions(120).allow({0, 1})}),
        card("card 2",
             {R("Ascale_x", 1, 20, "abscissa (time) scale of the function").zero_is(1.0).dims(dim::time),
              R("Fscale_y", 21, 40, "ordinate scale of the function").zero_is(1.0).dims(dim::velocity),
              R("Tstart", 41, 60, "time the velocity starts being imposed").dims(dim::time),
              R("Tstop", 61, 80, "time it stops being imposed; 0 = never").dims(dim::time)}),
    };
    k.dim_overrides = {{"Fscale_y", "Dir", {"XX", "YY", "ZZ"}, dim::rate}};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/IMPDISP",
           "imposed displacement of a node group from its initial position, following a function of time",
           Header::IdUnit, true, "impdisp_ID");
    k.cards = {
        card("card 1",
             {I("funct_IDT", 1, 10, "displacement versus time function").refs(IdKind::Other).must(),
              S("Dir", 11, 20, "direction: X, Y, Z (translation) or XX, YY, ZZ (rotation)"),
              I("skew_ID", 21, 30, "skew of the direction; 0 = global axes").refs(IdKind::Other),
              I("sensor_ID", 31, 40, "sensor that starts the displacement; 0 = none").refs(IdKind::Other),
              I("grnod_ID", 41, 50, "nodes concerned").refs(IdKind::Other),
              I("frame_ID", 51, 60, "moving frame of the direction (exclusive with skew); 0 = none")
                  .refs(IdKind::Other)
                  .versions(110),
              I("Icoor", 61, 70, "0 Cartesian, 1 cylindrical (with a frame)").versions(120).allow({0, 1})}),
        card("card 2",
             {R("Ascale_x", 1, 20, "abscissa (time) scale of the function").zero_is(1.0).dims(dim::time),
              R("Fscale_y", 21, 40, "ordinate scale of the function").zero_is(1.0).dims(dim::length),
              R("Tstart", 41, 60, "time the displacement starts being imposed").dims(dim::time),
              R("Tstop", 61, 80, "time it stops being imposed; 0 = never").dims(dim::time)}),
    };
    k.dim_overrides = {{"Fscale_y", "Dir", {"XX", "YY", "ZZ"}, dim::none}};
    t.push_back(std::move(k));
  }
  {
    // OpenRadioss read_impdisp_fgeo.F and fixfingeo.F (format 140, the only layout).
    KeywordDecl k =
        kw("/IMPDISP/FGEO",
           "prescribed final geometry: each listed node moves along the straight line from its "
           "initial position to its final position XN, the fraction of the way following a function "
           "of time",
           Header::Id, true, "impdisp_ID");
    k.cards = {
        card("card 1",
             {I("fct_ID", 1, 10, "function of time: the fraction of the way (0 at the start, 1 at the end)")
                  .refs(IdKind::Other)
                  .must(),
              I("part_ID", 11, 20,
                "spring part whose springs give the nodes (each first node goes to its second "
                "node's initial position); 0 = the listed nodes")
                  .refs(IdKind::Part),
              I("sens_ID", 31, 40, "sensor that starts the motion; 0 = none").refs(IdKind::Other)}),
        card("card 2",
             {R("Ascale", 1, 20,
                "time scale of the function: Radioss evaluates it at t * Ascale (not t / Ascale as /IMPDISP)")
                  .zero_is(1.0)
                  .dims(dim::time),
              R("Tstart", 41, 60, "time the motion starts being imposed").dims(dim::time),
              R("Tstop", 61, 80, "time it stops being imposed; 0 = never").dims(dim::time)}),
    };
    k.tail = Tail::Records;
    k.record = card("node", {I("node_IDN", 1, 10, "node moved").refs(IdKind::Node),
                             R("Xn", 11, 30, "final position X").dims(dim::length),
                             R("Yn", 31, 50, "final position Y").dims(dim::length),
                             R("Zn", 51, 70, "final position Z").dims(dim::length)});
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/INIVEL/TRA", "initial translational velocity of a node group", Header::IdUnit, true,
                       "inivel_ID");
    // /INIVEL/T+G sets the velocity of the structure and of the ALE grid: radx has no ALE grid, so it is the
    // translation of the nodes, as /INIVEL/TRA.
    k.aliases = {"/INIVEL/T+G"};
    k.cards = {
        card("card 1",
             {R("Vx", 1, 20, "initial X velocity").dims(dim::velocity),
              R("Vy", 21, 40, "initial Y velocity").dims(dim::velocity),
              R("Vz", 41, 60, "initial Z velocity").dims(dim::velocity),
              I("grnod_ID", 61, 70, "nodes concerned").refs(IdKind::Other),
              I("skew_ID", 71, 80, "skew of the velocity components; 0 = global axes").refs(IdKind::Other)}),
        card_v("card 2", 2025, kLastVersion,
               {R("Tstart", 1, 20, "time the velocity is imposed; 0 = at the start").dims(dim::time),
                I("sensor_ID", 21, 30, "sensor that triggers the velocity; 0 = none").refs(IdKind::Other)}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/INIVEL/ROT",
                       "initial angular velocity of a node group (the nodes' rotational degrees of freedom)",
                       Header::IdUnit, true, "inivel_ID");
    k.cards = {
        card("card 1",
             {R("Vx", 1, 20, "initial angular velocity about X").dims(dim::rate),
              R("Vy", 21, 40, "initial angular velocity about Y").dims(dim::rate),
              R("Vz", 41, 60, "initial angular velocity about Z").dims(dim::rate),
              I("grnod_ID", 61, 70, "nodes concerned").refs(IdKind::Other),
              I("skew_ID", 71, 80, "skew of the velocity components; 0 = global axes").refs(IdKind::Other)}),
        card_v("card 2", 2025, kLastVersion,
               {R("Tstart", 1, 20, "time the velocity is imposed; 0 = at the start").dims(dim::time),
                I("sensor_ID", 21, 30, "sensor that triggers the velocity; 0 = none").refs(IdKind::Other)}),
    };
    t.push_back(std::move(k));
  }
  for (const auto& [path, meaning, mass_meaning] :
       {std::tuple{"/ADMAS/0", "mass added to each node of a group (a point mass on each)",
                   "mass added to each node"},
        std::tuple{"/ADMAS/1", "mass added to a group, shared equally by its nodes",
                   "total mass shared by the nodes"}}) {
    KeywordDecl k = kw(path, meaning, Header::IdUnit, true, "admas_ID");
    k.cards = {card("card 1", {R("MASS", 1, 20, mass_meaning).dims(dim::mass).ge(0.0),
                               I("grnod_ID", 21, 30, "nodes concerned").refs(IdKind::Other).must()})};
    t.push_back(std::move(k));
  }
  // /FRAME/FIX and /FRAME/MOV have the cards of /SKEW/FIX and /SKEW/MOV (OpenRadioss hm_read_frm.F builds
  // their axes the same way) and share the skews' id space.
  for (const auto& [path, meaning, id_name] :
       {std::tuple{"/SKEW/FIX", "fixed frame: origin, Y' and Z' directions (x' = Y' x Z', y' = z' x x')",
                   "skew_ID"},
        std::tuple{"/FRAME/FIX",
                   "fixed reference frame: origin, Y' and Z' directions (x' = Y' x Z', y' = z' x x'); a "
                   "/TH/NODE in it measures positions from the origin",
                   "frame_ID"}}) {
    KeywordDecl k = kw(path, meaning, Header::IdUnit, true, id_name);
    k.cards = {card("card 1", {R("Ox", 1, 20, "origin X").dims(dim::length),
                               R("Oy", 21, 40, "origin Y").dims(dim::length),
                               R("Oz", 41, 60, "origin Z").dims(dim::length)}),
               card("card 2", {R("X1", 1, 20, "Y' direction, X component"),
                               R("Y1", 21, 40, "Y' direction, Y component"),
                               R("Z1", 41, 60, "Y' direction, Z component")}),
               card("card 3", {R("X2", 1, 20, "Z' direction, X component"),
                               R("Y2", 21, 40, "Z' direction, Y component"),
                               R("Z2", 41, 60, "Z' direction, Z component")})};
    t.push_back(std::move(k));
  }
  for (const auto& [path, meaning, id_name] :
       {std::tuple{"/SKEW/MOV",
                   "moving frame carried by three nodes: origin N1, the Dir axis along N1 -> N2, N3 in the "
                   "plane of the Dir axis and the next one; rebuilt from the nodes every cycle",
                   "skew_ID"},
        std::tuple{"/FRAME/MOV",
                   "moving reference frame carried by three nodes, built as /SKEW/MOV: origin N1, the Dir "
                   "axis along N1 -> N2, N3 in the plane of the Dir axis and the next one",
                   "frame_ID"}}) {
    KeywordDecl k = kw(path, meaning, Header::IdUnit, true, id_name);
    k.cards = {
        card("card 1", {I("N1", 1, 10, "origin node").refs(IdKind::Node).must(),
                        I("N2", 11, 20, "node giving the Dir axis from N1").refs(IdKind::Node).must(),
                        I("N3", 21, 30, "node in the plane of the Dir axis and the next one (X'Y' for X)")
                            .refs(IdKind::Node)
                            .must(),
                        S("Dir", 31, 40, "axis along N1 -> N2: X, Y or Z; blank = X").versions(2019)})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/ACCEL", "accelerometer: a node's acceleration in a skew frame, low-pass filtered",
                       Header::IdUnit, true, "accel_ID");
    k.cards = {card("card 1",
                    {I("node_ID", 1, 10, "node the accelerometer sits on").refs(IdKind::Node).must(),
                     I("skew_ID", 11, 20, "skew of the measured axes; 0 = global axes").refs(IdKind::Other),
                     R("Fcut", 31, 50, "cut-off frequency of the 4-pole Butterworth filter; 0 = none")
                         .dims(dim::rate)
                         .ge(0.0)})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/CLOAD", "concentrated force or moment on a node group, following a function",
                       Header::IdUnit, true, "cload_ID");
    k.cards = {
        card("card 1",
             {I("funct_IDT", 1, 10, "force versus time function").refs(IdKind::Other).must(),
              S("Dir", 11, 20, "direction: X, Y, Z (force) or XX, YY, ZZ (moment)"),
              I("skew_ID", 21, 30, "skew of the direction; 0 = global axes").refs(IdKind::Other),
              I("sensor_ID", 31, 40, "sensor that starts the load; 0 = none").refs(IdKind::Other),
              I("grnod_ID", 41, 50, "loaded nodes; each receives the full value").refs(IdKind::Other),
              I("Itypfun", 51, 60, "abscissa of the function: 1 time, 2 nodal displacement, 3 nodal velocity")
                  .versions(2023)
                  .zero_is(1)
                  .allow({0, 1, 2, 3}),
              R("Ascale_x", 61, 80, "abscissa (time) scale of the function").zero_is(1.0).dims(dim::time),
              R("Fscale_y", 81, 100, "ordinate scale of the function").zero_is(1.0).dims(dim::force)})};
    k.dim_overrides = {{"Fscale_y", "Dir", {"XX", "YY", "ZZ"}, dim::moment},
                       {"Ascale_x", "Itypfun", {"2"}, dim::length},
                       {"Ascale_x", "Itypfun", {"3"}, dim::velocity}};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/PLOAD", "pressure on a surface, following a function", Header::IdUnit, true, "pload_ID");
    k.cards = {
        card("card 1",
             {I("surf_ID", 1, 10, "loaded surface").refs(IdKind::Other),
              I("funct_IDT", 11, 20, "pressure versus time function").refs(IdKind::Other).must(),
              I("sensor_ID", 21, 30, "sensor that starts the load; 0 = none").refs(IdKind::Other),
              I("Ipinch", 31, 40, "apply the load to pinching degrees of freedom").versions(2020).unused(),
              I("Idel", 41, 50, "1 remove the load from deleted elements, 2 keep it")
                  .versions(2021)
                  .zero_is(1)
                  .allow({0, 1, 2}),
              I("Itypfun", 51, 60, "abscissa of the function: 1 time, 2 nodal displacement, 3 nodal velocity")
                  .versions(2023)
                  .zero_is(1)
                  .allow({0, 1, 2, 3}),
              R("Ascale_x", 61, 80, "abscissa (time) scale of the function").zero_is(1.0).dims(dim::time),
              R("Fscale_y", 81, 100, "ordinate scale of the function").zero_is(1.0).dims(dim::pressure)})};
    k.dim_overrides = {{"Ascale_x", "Itypfun", {"2"}, dim::length},
                       {"Ascale_x", "Itypfun", {"3"}, dim::velocity}};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/GRAV", "gravity acceleration on a node group", Header::IdUnit, true, "grav_ID");
    k.cards = {
        card("card 1",
             {I("funct_IDT", 1, 10, "acceleration versus time function; 0 = constant").refs(IdKind::Other),
              S("Dir", 11, 20, "direction: X, Y or Z (the sign comes from Fscale_y)"),
              I("skew_ID", 21, 30, "skew of the direction; 0 = global axes").refs(IdKind::Other),
              I("sensor_ID", 31, 40, "sensor that starts the load; 0 = none").refs(IdKind::Other),
              I("grnod_ID", 41, 50, "nodes concerned; 0 = all nodes").refs(IdKind::Other),
              R("Ascale_x", 61, 80, "abscissa (time) scale of the function").zero_is(1.0).dims(dim::time),
              R("Fscale_y", 81, 100, "acceleration, or ordinate scale of the function")
                  .zero_is(1.0)
                  .dims(dim::acceleration)})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/FUNCT", "piecewise-linear function y(x), one point per line", Header::Id, true, "funct_ID");
    k.tail = Tail::Records;
    k.record = card("point", {R("X", 1, 20, "abscissa; strictly increasing"), R("Y", 21, 40, "ordinate")});
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/MOVE_FUNCT",
           "scales then shifts an existing /FUNCT: X = X Ascalex + Ashiftx, Y = Y Fscaley + Fshifty",
           Header::Id, true, "funct_ID");
    k.cards = {card("card 1",
                    {R("Ascalex", 1, 20, "abscissa scale; 0 = 1; negative reverses the points").zero_is(1.0),
                     R("Fscaley", 21, 40, "ordinate scale; 0 = 1").zero_is(1.0),
                     R("Ashiftx", 41, 60, "abscissa shift, added after scaling"),
                     R("Fshifty", 61, 80, "ordinate shift, added after scaling")})};
    t.push_back(std::move(k));
  }
}

// ---------------------------------------------------------------------------------------------------------
// Model assembly: submodels and node transformations (OpenRadioss hm_read_submodel.F, lectrans.F,
// lectranssub.F and the CFG files SUBMODEL/submodel.cfg, TRANSFORM/{tra,rot,sca,sym}.cfg)
void add_assembly(std::vector<KeywordDecl>& t) {
  {
    KeywordDecl k =
        kw("//SUBMODEL",
           "start of a submodel: the keywords up to its //ENDSUB get its id offsets and unit system, "
           "and the /TRANSFORM cards naming it move its nodes",
           Header::IdUnit, true, "submodel_ID");
    k.id_kind = IdKind::Submodel;
    k.cards = {card("card 1", {I("off_def", 1, 10, "id offset of every object without an offset of its own"),
                               I("off_nod", 11, 20, "node id offset; 0 takes off_def"),
                               I("off_ele", 21, 30, "element id offset; 0 takes off_def"),
                               I("off_part", 31, 40, "part id offset; 0 takes off_def"),
                               I("off_mat", 41, 50, "material id offset; 0 takes off_def"),
                               I("off_type", 51, 60, "property id offset; 0 takes off_def"),
                               I("off_sub", 61, 70, "submodel id offset; 0 takes off_def")})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("//ENDSUB", "end of the innermost open //SUBMODEL", Header::None, false);
    t.push_back(std::move(k));
  }
  // The first card of /TRANSFORM/TRA, /ROT and /SYM: the moved nodes (a node group or a submodel), then
  // either coordinates or two nodes. sub_ID is read from the 100 layout on (TRA, ROT) or from 2026 (SYM).
  // x, y, z: the names of the three reals; what: the meaning of the first, then those of the other two.
  auto first_card = [](std::string_view x, std::string_view y, std::string_view z, std::string_view what,
                       std::string_view what_y, std::string_view what_z, int sub_since, Dim d) {
    return card(
        "card 1",
        {I("grnod_ID", 1, 10, "the nodes moved (exclusive with sub_ID)").refs(IdKind::Other),
         R(x, 11, 30, what).dims(d), R(y, 31, 50, what_y).dims(d), R(z, 51, 70, what_z).dims(d),
         I("node_ID1", 71, 80, "first node (with node_ID2, replaces the coordinates)").refs(IdKind::Node),
         I("node_ID2", 81, 90, "second node").refs(IdKind::Node),
         I("sub_ID", 91, 100, "the submodel moved: all its nodes (exclusive with grnod_ID)")
             .refs(IdKind::Submodel)
             .versions(sub_since)});
  };
  {
    KeywordDecl k = kw("/TRANSFORM/TRA", "translation of a node group or of a submodel's nodes",
                       Header::IdUnit, true, "transform_ID");
    k.cards = {first_card("X_translation", "Y_translation", "Z_translation",
                          "translation X component (node_ID1 to node_ID2 when they are given)",
                          "translation Y component", "translation Z component", 100, dim::length),
               card_v("card 2", 2026, kLastVersion,
                      {I("skew_ID", 1, 10, "skew the translation components are given in; 0 = global axes")
                           .refs(IdKind::Other)
                           .not_implemented()})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/TRANSFORM/ROT",
           "rotation of a node group or of a submodel's nodes about the axis from point 1 to point 2",
           Header::IdUnit, true, "transform_ID");
    k.cards = {
        first_card("X_point_1", "Y_point_1", "Z_point_1", "axis point 1 X (the centre; node_ID1 replaces it)",
                   "axis point 1 Y", "axis point 1 Z", 100, dim::length),
        card("card 2", {R("X_point_2", 11, 30, "axis point 2 X (node_ID2 replaces it)").dims(dim::length),
                        R("Y_point_2", 31, 50, "axis point 2 Y").dims(dim::length),
                        R("Z_point_2", 51, 70, "axis point 2 Z").dims(dim::length),
                        R("Angle", 71, 90, "rotation angle in degrees, right-handed about point 1 -> 2")})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/TRANSFORM/SCA", "scaling of a node group's (or a submodel's) coordinates about a centre node",
           Header::IdUnit, true, "transform_ID");
    k.cards = {
        card("card 1", {I("grnod_ID", 1, 10, "the nodes moved (exclusive with sub_ID)").refs(IdKind::Other),
                        R("Fscale_X", 11, 30, "X scale factor; 0 = 1").zero_is(1.0),
                        R("Fscale_Y", 31, 50, "Y scale factor; 0 = 1").zero_is(1.0),
                        R("Fscale_Z", 51, 70, "Z scale factor; 0 = 1").zero_is(1.0),
                        I("node_IDc", 71, 80, "centre node; 0 = the origin").refs(IdKind::Node),
                        I("sub_ID", 91, 100, "the submodel moved: all its nodes (exclusive with grnod_ID)")
                            .refs(IdKind::Submodel)
                            .versions(2026)})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/TRANSFORM/SYM",
           "mirror of a node group or of a submodel's nodes in the plane through point 1 normal to "
           "point 1 -> 2",
           Header::IdUnit, true, "transform_ID");
    k.cards = {
        first_card("X_point_1", "Y_point_1", "Z_point_1", "point 1 X, on the plane (node_ID1 replaces it)",
                   "point 1 Y", "point 1 Z", 2026, dim::length),
        card("card 2",
             {R("X_point_2", 11, 30, "point 2 X: point 1 -> 2 is the plane normal").dims(dim::length),
              R("Y_point_2", 31, 50, "point 2 Y").dims(dim::length),
              R("Z_point_2", 51, 70, "point 2 Z").dims(dim::length)})};
    t.push_back(std::move(k));
  }
}

// ---------------------------------------------------------------------------------------------------------
// Sensors (OpenRadioss read_sensor_time.F; sensor_time.cfg: Tstop from the 2023 format). The other sensor
// types are Radioss keywords radx does not read (RX302 naming the type).
void add_sensors(std::vector<KeywordDecl>& t) {
  KeywordDecl k = kw("/SENSOR/TIME", "sensor that switches on at a given time (and off again at Tstop)",
                     Header::IdUnit, true, "sens_ID");
  k.aliases = {"/SENSOR/TYPE0"};
  k.cards = {
      card("card 1", {R("Tdelay", 1, 20, "time the sensor switches on").dims(dim::time)}),
      card_v("card 2", 2023, kLastVersion,
             {R("Tstop", 1, 20, "time the sensor switches off again; 0 = never").dims(dim::time)}),
  };
  t.push_back(std::move(k));
}

// ---------------------------------------------------------------------------------------------------------
// Rigid wall, rigid body
// The /RWALL family: the cards of /RWALL/PLANE, with the diameter on card 2 for the curved walls, no M1 for
// the sphere and a corner M2 for the parallelogram (OpenRadioss hm_read_rwall_*.F, one layout per shape).
enum class WallShape { Plane, Cylinder, Sphere, Parallelogram };

KeywordDecl rigid_wall(std::string_view path, std::string_view meaning, WallShape shape) {
  const bool curved = shape == WallShape::Cylinder || shape == WallShape::Sphere;
  const bool paral = shape == WallShape::Parallelogram;
  const std::string_view d_meaning =
      curved ? "search distance: nodes outside the wall within it become secondary"
             : "search distance: nodes on the positive side within it become secondary";
  auto diameter = [&] {
    return curved ? R("Diameter", 41, 60, "diameter").dims(dim::length).must().gt(0.0)
                  : R("Diameter", 41, 60, "cylinder or sphere diameter, unused for a plane")
                        .dims(dim::length)
                        .unused();
  };
  // Radioss's parallelogram wall never filters the friction (rgwalp.F): ffac and ifq are read, unused.
  auto ffac = R("ffac", 61, 80, "friction filtering factor");
  auto ifq = I("ifq", 81, 90, "friction filtering: 0 none, 1 user factor, 2 period, 3 cut-off frequency")
                 .allow({0, 1, 2, 3});
  if (paral) {
    ffac.unused();
    ifq.unused();
  }
  std::vector<FieldDecl> card2_other = {R("d", 1, 20, d_meaning).dims(dim::length)};
  if (curved) card2_other.push_back(diameter());
  // Texts of the point M (string literals: the declarations keep views of them).
  using Texts = std::array<std::string_view, 3>;
  const Texts m_what =
      shape == WallShape::Plane
          ? Texts{"point M on the wall, X", "point M on the wall, Y", "point M on the wall, Z"}
      : shape == WallShape::Cylinder
          ? Texts{"point M on the axis, X", "point M on the axis, Y", "point M on the axis, Z"}
      : shape == WallShape::Sphere ? Texts{"centre M, X", "centre M, Y", "centre M, Z"}
                                   : Texts{"corner M of the parallelogram, X", "corner M, Y", "corner M, Z"};
  KeywordDecl k = kw(path, meaning, Header::IdUnit, true, "rwall_ID");
  k.cards = {
      card("card 1",
           {I("node_ID", 1, 10, "node carrying a moving wall; 0 = fixed wall").refs(IdKind::Node),
            I("Slide", 11, 20, "0 frictionless sliding, 1 tied, 2 Coulomb friction").allow({0, 1, 2}),
            I("grnd_ID1", 21, 30, "secondary nodes").refs(IdKind::Other),
            I("grnd_ID2", 31, 40, "nodes removed from the secondary set").refs(IdKind::Other),
            I("Iform", 41, 50, "0 kinematic, 1 penalty").versions(2026).allow({0, 1})}),
      card_if("card 2 (Slide = 2)", when_eq("Slide", 2),
              {R("d", 1, 20, d_meaning).dims(dim::length),
               R("fric", 21, 40, "Coulomb friction coefficient").ge(0.0), diameter(), std::move(ffac),
               std::move(ifq)}),
      card_if("card 2 (Slide != 2)", when_ne("Slide", 2), std::move(card2_other)),
      card_if("card 3 (fixed wall)", when_eq("node_ID", 0),
              {R("XM", 1, 20, m_what[0]).dims(dim::length), R("YM", 21, 40, m_what[1]).dims(dim::length),
               R("ZM", 41, 60, m_what[2]).dims(dim::length)}),
      card_if("card 3 (moving wall)", when_gt("node_ID", 0),
              {R("Mass", 1, 20, "mass added to the wall node").dims(dim::mass),
               R("VX0", 21, 40, "initial X velocity of the wall node").dims(dim::velocity),
               R("VY0", 41, 60, "initial Y velocity of the wall node").dims(dim::velocity),
               R("VZ0", 61, 80, "initial Z velocity of the wall node").dims(dim::velocity)}),
  };
  if (shape == WallShape::Plane)
    k.cards.push_back(card(
        "card 4", {R("XM1", 1, 20, "second point M1, X; the normal points from M to M1").dims(dim::length),
                   R("YM1", 21, 40, "second point M1, Y").dims(dim::length),
                   R("ZM1", 41, 60, "second point M1, Z").dims(dim::length)}));
  if (shape == WallShape::Cylinder)
    k.cards.push_back(
        card("card 4",
             {R("XM1", 1, 20, "second point M1 on the axis, X; the axis runs from M to M1").dims(dim::length),
              R("YM1", 21, 40, "second point M1, Y").dims(dim::length),
              R("ZM1", 41, 60, "second point M1, Z").dims(dim::length)}));
  if (paral) {
    k.cards.push_back(
        card("card 4", {R("XM1", 1, 20, "corner M1, X: the first edge runs from M to M1").dims(dim::length),
                        R("YM1", 21, 40, "corner M1, Y").dims(dim::length),
                        R("ZM1", 41, 60, "corner M1, Z").dims(dim::length)}));
    k.cards.push_back(card("card 5", {R("XM2", 1, 20,
                                        "corner M2, X: the second edge runs from M to M2; the wall acts on "
                                        "the side of (M1 - M) x (M2 - M)")
                                          .dims(dim::length),
                                      R("YM2", 21, 40, "corner M2, Y").dims(dim::length),
                                      R("ZM2", 41, 60, "corner M2, Z").dims(dim::length)}));
  }
  return k;
}

void add_rigid(std::vector<KeywordDecl>& t) {
  t.push_back(
      rigid_wall("/RWALL/PLANE", "infinite rigid plane wall acting on secondary nodes", WallShape::Plane));
  t.push_back(rigid_wall("/RWALL/CYL",
                         "infinite rigid cylinder (axis through M and M1) keeping secondary nodes outside",
                         WallShape::Cylinder));
  t.push_back(rigid_wall("/RWALL/SPHER", "rigid sphere (centre M) keeping secondary nodes outside",
                         WallShape::Sphere));
  t.push_back(
      rigid_wall("/RWALL/PARAL",
                 "finite rigid plane wall, the parallelogram of corner M and edges M M1 and M M2, stopping "
                 "the secondary nodes whose path crosses it",
                 WallShape::Parallelogram));
  {
    KeywordDecl k =
        kw("/RBODY", "rigid body: a main node driving a node group", Header::IdUnit, true, "rbody_ID");
    k.cards = {
        card("card 1",
             {I("node_ID", 1, 10, "main node; 0 creates one").refs(IdKind::Node),
              I("sens_ID", 11, 20,
                "sensor that releases the body (2 cycles after it switches on); 0 = rigid throughout")
                  .refs(IdKind::Other),
              I("skew_ID", 21, 30, "frame of the added inertia; 0 = global axes").refs(IdKind::Other),
              I("Ispher", 31, 40, "1 spherical inertia, 2 full inertia tensor").zero_is(2).allow({0, 1, 2}),
              R("Mass", 41, 60, "mass added to the main node").dims(dim::mass),
              I("grnd_ID", 61, 70, "secondary nodes").refs(IdKind::Other),
              I("Ikrem", 71, 80, "handling of secondary nodes also on a rigid wall").unused(),
              I("ICoG", 81, 90, "centre of gravity and main node position option")
                  .zero_is(1)
                  .allow({0, 1, 2, 3, 4}),
              I("surf_ID", 91, 100, "surface linked to the body").refs(IdKind::Other).unused()}),
        card("card 2", {R("Jxx", 1, 20, "added inertia xx").dims(dim::inertia),
                        R("Jyy", 21, 40, "added inertia yy").dims(dim::inertia),
                        R("Jzz", 41, 60, "added inertia zz").dims(dim::inertia)}),
        card("card 3", {R("Jxy", 1, 20, "added inertia xy").dims(dim::inertia),
                        R("Jyz", 21, 40, "added inertia yz").dims(dim::inertia),
                        R("Jxz", 41, 60, "added inertia xz").dims(dim::inertia)}),
        card_v("card 4", 110, kLastVersion,
               {I("Ioptoff", 1, 10, "1 = elements entirely inside the body are not computed")
                    .allow({0, 1})
                    .not_implemented(),
                I("Iexpams", 11, 20, "AMS expansion flag").versions(2017).unused(),
                I("Ifail", 21, 30, "failure criterion; >0 reads card 5").versions(2021).not_implemented()}),
        card_v("card 5 (Ifail > 0)", 2021, kLastVersion,
               {R("FN", 1, 20, "normal failure force").zero_is(1e20).dims(dim::force).unused(),
                R("FT", 21, 40, "tangential failure force").zero_is(1e20).dims(dim::force).unused(),
                R("expN", 41, 60, "normal failure exponent").zero_is(2.0).unused(),
                R("expT", 61, 80, "tangential failure exponent").zero_is(2.0).unused()}),
    };
    k.cards.back().condition = when_gt("Ifail", 0);
    t.push_back(std::move(k));
  }
}

// ---------------------------------------------------------------------------------------------------------
// Sections (OpenRadioss hm_read_sect.F; the reading of the card is radx's own)
void add_sections(std::vector<KeywordDecl>& t) {
  KeywordDecl k =
      kw("/SECT", "section cut: the force and moment that the listed elements apply to a set of nodes",
         Header::IdUnit, true, "sect_ID");
  k.cards = {
      card("card 1",
           {I("node_ID1", 1, 10, "N1: origin of the section frame; 0 = global frame, normal Z (Iframe >= 10)")
                .refs(IdKind::Node),
            I("node_ID2", 11, 20, "N2: axis 1 of the frame points from N1 to N2").refs(IdKind::Node),
            I("node_ID3", 21, 30, "N3: with N1 and N2 spans the section plane").refs(IdKind::Node),
            I("grnod_ID", 31, 40, "nodes of the cut, where the element forces are summed")
                .refs(IdKind::Other)
                .must(),
            I("I_SAVE", 41, 50,
              "cut file: 0 none, 1 or 2 write displacements (and forces), 100, 101 or 200 read "
              "them as input")
                .allow({0, 1, 2, 100, 101, 200}),
            I("Frame_ID", 51, 60, "moving frame defining the section; 0 = the nodes N1 N2 N3")
                .refs(IdKind::Other),
            R("Dt", 61, 80, "time step of the cut file").dims(dim::time).unused(),
            R("alpha", 81, 100, "filtering coefficient of the cut file (< 1)").unused()}),
      card("card 2", {S("file_name", 1, 100, "root name of the cut file (I_SAVE > 0)")}),
      card("card 3",
           {I("grbric_ID", 1, 10, "bricks whose forces are summed (/GRBRIC)").refs(IdKind::Other),
            I("grshel_ID", 21, 30, "4-node shells whose forces and moments are summed (/GRSHEL)")
                .refs(IdKind::Other),
            I("grtrus_ID", 31, 40, "trusses (/GRTRUS)").refs(IdKind::Other),
            I("grbeam_ID", 41, 50, "beams (/GRBEAM)").refs(IdKind::Other),
            I("grsprg_ID", 51, 60, "springs (/GRSPRI)").refs(IdKind::Other),
            I("grtria_ID", 61, 70, "3-node shells whose forces and moments are summed (/GRSH3N)")
                .refs(IdKind::Other),
            I("Ninter", 71, 80, "number of interfaces whose contact forces are added (at most 10)"),
            I("Iframe", 91, 100,
              "frame and moment centre: 0..3 local frame of N1 N2 N3, 10..13 global axes; the last digit "
              "puts the centre at 0 the projection of N3 on N1N2, 1 the nodes' mean, 2 their mass centre, 3 "
              "the origin")
                .allow({0, 1, 2, 3, 10, 11, 12, 13})}),
      card_if("card 4 (Ninter > 0)", when_gt("Ninter", 0),
              {I("inter_ID1", 1, 10, "interface 1").refs(IdKind::Other),
               I("inter_ID2", 11, 20, "interface 2").refs(IdKind::Other),
               I("inter_ID3", 21, 30, "interface 3").refs(IdKind::Other),
               I("inter_ID4", 31, 40, "interface 4").refs(IdKind::Other),
               I("inter_ID5", 41, 50, "interface 5").refs(IdKind::Other),
               I("inter_ID6", 51, 60, "interface 6").refs(IdKind::Other),
               I("inter_ID7", 61, 70, "interface 7").refs(IdKind::Other),
               I("inter_ID8", 71, 80, "interface 8").refs(IdKind::Other),
               I("inter_ID9", 81, 90, "interface 9").refs(IdKind::Other),
               I("inter_ID10", 91, 100, "interface 10").refs(IdKind::Other)}),
  };
  t.push_back(std::move(k));
}

// ---------------------------------------------------------------------------------------------------------
// Time history
void add_time_history(std::vector<KeywordDecl>& t) {
  // What follows the variable lines: ids 10 per line, or one object per line with or without a skew
  // (the reference reader decodes a skew on /TH/NODE, /TH/SHEL and /TH/SH3N lines only). The element lines of
  // /TH/SHEL have no skew_ID before the 140 layout (columns 11-20 blank).
  enum class Objects { Ids, RecordsWithSkew, Records };
  auto th = [&t](std::string_view path, std::vector<std::string_view> aliases, std::string_view meaning,
                 Objects objects, int skew_since = kAnyVersion) {
    KeywordDecl k = kw(path, meaning, Header::Id, true, "th_ID");
    k.aliases = std::move(aliases);
    k.tail = objects == Objects::Ids ? Tail::ThVarsThenIds : Tail::ThVarsThenRecords;
    const auto word = path.substr(4);
    k.list_kind = word == "NODE"                                                           ? IdKind::Node
                  : word == "SHEL" || word == "SH3N" || word == "BRIC" || word == "SPRING" ? IdKind::Element
                  : word == "PART"                                                         ? IdKind::Part
                                                                                           : IdKind::Other;
    if (objects == Objects::RecordsWithSkew)
      k.record = card(
          "object",
          {I("id", 1, 10, "object id").refs(k.list_kind),
           I("skew_ID", 11, 20, "skew of the output; 0 = global").refs(IdKind::Other).versions(skew_since),
           S("name", 21, 100, "label of the object in the output")});
    else if (objects == Objects::Records)
      k.record = card("object", {I("id", 1, 10, "object id").refs(k.list_kind),
                                 S("name", 21, 100, "label of the object in the output")});
    t.push_back(std::move(k));
  };
  th("/TH/NODE", {}, "time history of nodal variables", Objects::RecordsWithSkew);
  th("/TH/PART", {}, "time history of part energies and momenta", Objects::Ids);
  th("/TH/INTER", {}, "time history of interface forces and energies", Objects::Ids);
  th("/TH/RWALL", {}, "time history of rigid wall forces", Objects::Ids);
  th("/TH/SHEL", {"/TH/SHELL"}, "time history of shell element results", Objects::RecordsWithSkew, 140);
  th("/TH/SUBS", {}, "time history of subset energies and momenta", Objects::Ids);
  th("/TH/BRIC", {"/TH/BRICK"}, "time history of brick element results", Objects::Records);
  th("/TH/SH3N", {}, "time history of 3-node shell element results", Objects::RecordsWithSkew);
  th("/TH/RBODY", {}, "time history of rigid body forces and motion", Objects::Ids);
  th("/TH/SECTIO", {}, "time history of section forces and moments", Objects::Ids);
  th("/TH/ACCEL", {}, "time history of accelerometers", Objects::Ids);
  th("/TH/SPRING", {}, "time history of spring forces, elongations and energies", Objects::Records);
  th("/TH/TRUSS", {}, "time history of truss forces, energies and plastic strains", Objects::Records);
  th("/TH/BEAM", {}, "time history of beam forces, moments, energies and plastic strains", Objects::Records);
}

// ---------------------------------------------------------------------------------------------------------
// Global defaults and control cards
void add_defaults_and_controls(std::vector<KeywordDecl>& t) {
  {
    KeywordDecl k =
        kw("/DEF_SHELL", "global defaults for shell property flags left at 0", Header::None, false);
    k.singleton = true;
    k.cards = {card(
        "card 1", {I("Ishell", 1, 10, "default 4-node shell formulation"),
                   I("Ismstr", 11, 20, "default shell strain formulation"),
                   I("Ithick", 21, 30, "default thickness update flag"),
                   I("Iplas", 31, 40, "default plane-stress plasticity"),
                   I("Istrain", 41, 50, "strain output flag, ignored by the reference starter").unused(),
                   I("Ioffset", 51, 60, "1 = shell offset used in contact").versions(2024).not_implemented(),
                   I("Ish3n", 71, 80, "default 3-node shell formulation"),
                   I("Idrill", 81, 90, "default drilling stiffness flag").versions(110),
                   I("Ithin_drape", 91, 100, "drape thinning option").versions(2026).zero_is(1).unused()})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/DEF_SOLID", "global defaults for solid property flags left at 0", Header::None, false);
    k.singleton = true;
    k.cards = {card(
        "card 1",
        {I("Isolid", 1, 10, "default 8-node solid formulation"),
         I("Ismstr", 11, 20, "default solid strain formulation"),
         I("Icpre", 21, 30, "default constant-pressure option").versions(2021),
         I("Istrain", 31, 40, "strain output flag, ignored").versions(100, 2020).unused(),
         I("Itetra4", 41, 50, "default 4-node tetra formulation (see /PROP/SOLID Itetra4)").versions(2019),
         I("Itetra10", 51, 60, "default 10-node tetra formulation").versions(2019).unused(),
         I("Imas", 61, 70, "nodal mass distribution: 1 by angle, 2 uniform").versions(120).not_implemented(),
         I("Iframe", 71, 80, "default element frame"),
         I("Icontrol", 81, 90, "default distortion control").versions(2025).unused()})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/ANALY", "analysis type and parallel arithmetic switch", Header::None, false);
    k.support = Support::Ignored;
    k.singleton = true;
    k.cards = {
        card("card 1",
             {I("N2D3D", 1, 10, "0 3-D, 1 axisymmetric, 2 plane strain").allow({0, 1, 2}).not_implemented(),
              I("ITEMP", 11, 20, "temperature also evolves in expansion").versions(2026),
              I("IPARITH", 21, 30, "parallel arithmetic: 1 on, 2 off").zero_is(1).allow({0, 1, 2}),
              I("ISUBCYC", 31, 40, "subcycling flag, ignored").versions(kAnyVersion, 2022)})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/IOFLAG", "listing and output format options", Header::None, false);
    k.support = Support::Ignored;
    k.singleton = true;
    k.cards = {card("card 1",
                    {I("IPRI", 1, 10, "listing detail level"),
                     I("IGTYP", 21, 30, "geometry output type of old layouts").versions(kAnyVersion, 140),
                     I("IOUTP", 31, 40, "starter geometry output in animation format"),
                     I("IOUTYY", 41, 50, "output format option").versions(100),
                     I("IROOTYY", 51, 60, "root-name format option").versions(100),
                     I("Irot", 61, 70, "1 = always compute rotational degrees of freedom").versions(100)})};
    t.push_back(std::move(k));
  }
  {
    // The reference reads `/RANDOM/x/...` as /RANDOM whenever x is not GRNOD: old decks write /RANDOM/0.
    KeywordDecl k = kw("/RANDOM", "random perturbation of all node coordinates; a trailing /0 is ignored",
                       Header::OptionalId, false, "ignored_ID");
    k.cards = {
        card("card 1", {R("XALEA", 1, 20, "largest random perturbation of each coordinate; 0 = none")
                            .dims(dim::length)
                            .ge(0.0),
                        R("SEED", 21, 40, "seed of Radioss's random sequence; 0 = the default sequence")})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/RANDOM/GRNOD", "random perturbation of a node group's coordinates", Header::Id,
                       false, "grnod_ID");
    k.cards = {
        card("card 1", {R("XALEA", 1, 20, "largest random perturbation of each coordinate; 0 = none")
                            .dims(dim::length)
                            .ge(0.0),
                        R("SEED", 21, 40, "seed of Radioss's random sequence; 0 = the default sequence")})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/ANIM/VERS", "animation file format version (output only)", Header::None, false);
    k.support = Support::Ignored;
    k.singleton = true;
    k.cards = {card("card 1", {I("ANIM_VERS", 1, 10, "format version of the animation files")})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/MEMORY", "memory reservation of old Radioss versions (radx allocates as it reads)",
                       Header::None, false);
    k.support = Support::Ignored;
    k.singleton = true;
    k.cards = {card("card 1", {I("MEMORY", 1, 10, "words of memory to reserve"),
                               R("REAL", 21, 40, "share of the memory for reals")})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/SPMD", "domain decomposition and thread settings", Header::None, false);
    k.support = Support::Ignored;
    k.singleton = true;
    k.cards = {
        card("card 1", {I("Domdec", 1, 10, "decomposition method"), I("Nspmd", 11, 20, "number of domains"),
                        I("Dkword", 31, 40, "decomposition option"),
                        I("Nthread", 51, 60, "threads per domain").versions(110)})};
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/SHFRA/V4", "selects the old shell local frame definition", Header::None, false);
    k.aliases = {"/SHFRA"};
    k.support = Support::Ignored;
    k.singleton = true;
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k = kw("/END", "end of the starter deck", Header::None, false);
    k.singleton = true;
    t.push_back(std::move(k));
  }
}

// /MAT/OGDEN (law 42): Ogden's hyperelastic rubber (OpenRadioss hm_read_mat42.F; layouts of the radioss110,
// 140 and 2025 cfg files: Iform from 140 on, the card of mu_6..mu_10 and alpha_6..alpha_10 blank before 140).
// The Prony series (M > 0, then its cards) and the tabulated bulk function are refused by name.
void add_ogden(std::vector<KeywordDecl>& t) {
  KeywordDecl k =
      kw("/MAT/LAW42",
         "Ogden hyperelastic material: W = sum mu_p / alpha_p (lambda1b^alpha_p + lambda2b^alpha_p + "
         "lambda3b^alpha_p - 3) + U(J), one-point bricks",
         Header::IdUnit, true, "mat_ID");
  k.aliases = {"/MAT/OGDEN"};
  // Literal names: the declarations hold string_views.
  auto mu = [](std::string_view name, int first) {
    return R(name, first, first + 19, "shear parameter mu_p of the term").dims(dim::pressure);
  };
  auto alpha = [](std::string_view name, int first) {
    return R(name, first, first + 19, "exponent alpha_p of the term");
  };
  k.cards = {
      card("card 1", {R("RHO_I", 1, 20, "initial density").must().gt(0.0).dims(dim::density),
                      R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I").dims(dim::density)}),
      card("card 2",
           {R("nu", 1, 20, "Poisson's ratio, gives the bulk modulus; 0 = 0.495").zero_is(0.495),
            R("sigma_cut", 21, 40,
              "tension cut-off on the principal Biot stress (the element is deleted); 0 = 1e20")
                .zero_is(1e20)
                .dims(dim::pressure),
            I("Jstrain", 41, 50, "strain formulation flag of the cfg file; OpenRadioss does not read it")
                .unused(),
            I("fct_IDbulk", 51, 60, "function of the bulk modulus against J (tabulated bulk)")
                .refs(IdKind::Other)
                .not_implemented(),
            R("Fscale_bulk", 61, 80, "scale of fct_IDbulk").unused(),
            I("M", 81, 90, "number of Prony terms of the visco-elastic part").not_implemented(),
            I("Iform", 91, 100, "volumetric energy: 1 U = K/2 (J-1)^2, 2 U = K (J - 1 - ln J); 0 = 1")
                .versions(140)
                .allow({0, 1, 2})}),
      card("card 3", {mu("mu_1", 1), mu("mu_2", 21), mu("mu_3", 41), mu("mu_4", 61), mu("mu_5", 81)}),
      card("card 4", {mu("mu_6", 1), mu("mu_7", 21), mu("mu_8", 41), mu("mu_9", 61), mu("mu_10", 81)}),
      card("card 5", {alpha("alpha_1", 1), alpha("alpha_2", 21), alpha("alpha_3", 41), alpha("alpha_4", 61),
                      alpha("alpha_5", 81)}),
      card("card 6", {alpha("alpha_6", 1), alpha("alpha_7", 21), alpha("alpha_8", 41), alpha("alpha_9", 61),
                      alpha("alpha_10", 81)}),
  };
  t.push_back(std::move(k));
}

// /MAT/FOAM_TAB (law 70): tabulated visco-elastic foam (OpenRadioss hm_read_mat70.F; layouts of the
// radioss51, 90 and 120 cfg files: Iflag, Shape and Hys from 90 on, Itens and its card from 120 on). One line
// per curve: function, strain rate, scale. radx reads up to kFoamMaxCurves loading and as many unloading
// curves.
constexpr int kFoamMaxCurves = 10;
std::string_view foam_name(int list, int k) {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const char* base :
         {"fct_L", "rate_L", "scale_L", "fct_U", "rate_U", "scale_U", "loading curve ", "unloading curve "})
      for (int i = 1; i <= kFoamMaxCurves; ++i) v.push_back(base + std::to_string(i));
    return v;
  }();
  return names[static_cast<std::size_t>(list * kFoamMaxCurves + k)];
}

void add_foam_tab(std::vector<KeywordDecl>& t) {
  KeywordDecl k = kw("/MAT/LAW70",
                     "tabulated visco-elastic foam: loading curves per strain rate, unloading curve, "
                     "hysteresis; one-point bricks",
                     Header::IdUnit, true, "mat_ID");
  k.aliases = {"/MAT/FOAM_TAB"};
  k.cards = {
      card("card 1", {R("RHO_I", 1, 20, "initial density").must().gt(0.0).dims(dim::density),
                      R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I").dims(dim::density)}),
      card("card 2",
           {R("E0", 1, 20, "initial Young's modulus (raised to the first slope of the loading curves)")
                .must()
                .gt(0.0)
                .dims(dim::pressure),
            R("nu", 21, 40, "Poisson's ratio"),
            R("E_max", 41, 60, "largest Young's modulus; 0 = the largest slope of the loading curves")
                .ge(0.0)
                .dims(dim::pressure),
            R("Eps_max", 61, 80, "strain beyond which the curves continue with the slope E_max; 0 = 1")
                .zero_is(1.0)
                .gt(0.0),
            I("Itens", 81, 90, "1: the stress in expansion times fctIDTens(1 - rho / rho0)")
                .versions(120)
                .allow({0, 1})}),
      card("card 3",
           {R("Fcut", 1, 20, "cut-off frequency of the strain-rate filter; 0 = none").ge(0.0).dims(dim::rate),
            I("Ismooth", 21, 30, "strain-rate filter flag (Fcut > 0 sets it)").allow({0, 1}),
            I("Nload", 31, 40, "number of loading curves (strain rates), 1 to 10")
                .must()
                .ge(1)
                .le(kFoamMaxCurves),
            I("Nunload", 41, 50, "number of unloading curves, 0 to 10").ge(0).le(kFoamMaxCurves),
            I("Iflag", 51, 60,
              "unloading: 0 curves, 1 deviator and 2 stress times unload/static curve, 3 deviator and 4 "
              "stress by the dissipated energy (Shape, Hys)")
                .versions(90)
                .allow({0, 1, 2, 3, 4}),
            R("Shape", 61, 80, "exponent of the energy ratio of Iflag 3 and 4; 0 = 1")
                .versions(90)
                .zero_is(1.0),
            R("Hys", 81, 100, "hysteresis factor of Iflag 3 and 4; 0 = 1").versions(90).zero_is(1.0)}),
  };
  for (int list = 0; list < 2; ++list)
    for (int i = 0; i < kFoamMaxCurves; ++i) {
      const int b = 3 * list;
      k.cards.push_back(card_if(
          foam_name(6 + list, i), when_gt(list == 0 ? "Nload" : "Nunload", i),
          {I(foam_name(b, i), 1, 10, list == 0 ? "loading curve sigma(eps)" : "unloading curve sigma(eps)")
               .refs(IdKind::Other),
           R(foam_name(b + 1, i), 11, 30, "strain rate of the curve").ge(0.0).dims(dim::rate),
           R(foam_name(b + 2, i), 31, 50, "scale of the curve's ordinates; 0 = 1")
               .zero_is(1.0)
               .dims(dim::pressure)}));
    }
  {
    CardDecl c = card_if("tension card", when_eq("Itens", 1),
                         {I("fctIDTens", 1, 10, "factor of the stress against 1 - rho / rho0 in expansion")
                              .refs(IdKind::Other),
                          R("FscaleTens", 11, 30, "scale of that factor; 0 = 1").zero_is(1.0)});
    c.since = 120;
    k.cards.push_back(std::move(c));
  }
  t.push_back(std::move(k));
}

// /MAT/VOID and /MAT/RIGID compute no internal force (OpenRadioss hm_read_mat00.F, hm_read_mat13.F): their
// E and nu give the contact stiffness and, for the rigid law, a stable step only.
void add_void_and_rigid(std::vector<KeywordDecl>& t) {
  {
    KeywordDecl k = kw("/MAT/LAW0", "void material: no stiffness, for contact surfaces and mass-less parts",
                       Header::IdUnit, true, "mat_ID");
    k.aliases = {"/MAT/VOID", "/MAT/LAW00"};
    // The card is optional (a free card in OpenRadioss's layout): a blank or missing one is a void without
    // mass or contact stiffness.
    k.cards = {
        card("card 1 (optional)",
             {R("RHO_I", 1, 20, "density of the element mass; 0 or blank = no mass")
                  .ge(0.0)
                  .dims(dim::density),
              R("E", 21, 40, "Young's modulus, used only for the contact stiffness")
                  .ge(0.0)
                  .dims(dim::pressure),
              R("nu", 41, 60, "Poisson's ratio, used only for the contact stiffness (bulk modulus)")}),
    };
    t.push_back(std::move(k));
  }
  {
    KeywordDecl k =
        kw("/MAT/LAW13", "rigid material: each connected set of its elements moves as one rigid body",
           Header::IdUnit, true, "mat_ID");
    k.aliases = {"/MAT/RIGID"};
    k.cards = {
        card("card 1", {R("RHO_I", 1, 20, "density: the rigid body's mass is rho_I V of its elements")
                            .must()
                            .gt(0.0)
                            .dims(dim::density),
                        R("RHO_ref", 21, 40, "reference density; 0 takes RHO_I").dims(dim::density)}),
        card("card 2", {R("E", 1, 20, "Young's modulus, used only for the contact stiffness")
                            .must()
                            .gt(0.0)
                            .dims(dim::pressure),
                        R("nu", 21, 40,
                          "Poisson's ratio, used only for the contact stiffness; 0.5 is taken as 0.499")}),
    };
    t.push_back(std::move(k));
  }
}

}  // namespace

const std::vector<KeywordDecl>& starter_keywords() {
  static const std::vector<KeywordDecl> table = [] {
    std::vector<KeywordDecl> t;
    add_control_and_mesh(t);
    add_assembly(t);
    add_properties_and_materials(t);
    add_plas_tab_and_failure(t);
    add_plas_brit(t);
    add_void_and_rigid(t);
    add_ogden(t);
    add_foam_tab(t);
    add_groups(t);
    add_contact(t);
    add_loads(t);
    add_sensors(t);
    add_rigid(t);
    add_sections(t);
    add_time_history(t);
    add_defaults_and_controls(t);
    return t;
  }();
  return table;
}

const std::vector<std::string_view>& known_unsupported_roots() {
  static const std::vector<std::string_view> roots = [] {
    return std::vector<std::string_view>{
        // materials
        "/MAT/LAW3", "/MAT/HYDPLA", "/MAT/LAW4", "/MAT/HYD_JCOOK", "/MAT/LAW6", "/MAT/HYDRO", "/MAT/LAW10",
        "/MAT/LAW19", "/MAT/FABRI", "/MAT/LAW25", "/MAT/COMPSH", "/MAT/LAW32", "/MAT/HILL", "/MAT/LAW34",
        "/MAT/BOLTZMAN", "/MAT/LAW44", "/MAT/COWPER", "/MAT/LAW57", "/MAT/BARLAT3", "/MAT/LAW58",
        "/MAT/LAW62", "/MAT/LAW65", "/MAT/LAW66", "/MAT/LAW69", "/MAT/LAW87", "/MAT/LAW88", "/MAT/LAW90",
        "/MAT/LAW109", "/MAT/PLAS_ZERIL", "/MAT/ZHAO", "/MAT/USER",
        // properties
        "/PROP/TYPE0", "/PROP/VOID", "/PROP/TYPE9", "/PROP/SH_ORTH", "/PROP/TYPE10", "/PROP/SH_COMP",
        "/PROP/TYPE11", "/PROP/SH_SANDW", "/PROP/TYPE16", "/PROP/SH_FABR", "/PROP/TYPE17", "/PROP/TYPE18",
        "/PROP/INT_BEAM", "/PROP/TYPE20", "/PROP/TSHELL", "/PROP/TYPE22", "/PROP/TYPE23", "/PROP/TYPE51",
        "/PROP/TYPE52", "/PROP/USER",
        // elements
        "/TETRA10", "/PENTA6", "/SHEL16", "/QUAD", "/TRIA", "/SPHCEL",
        // groups, surfaces, boxes
        "/GRNOD/LINE", "/GRSHEL", "/GRSH3N", "/GRBRIC", "/GRSPRI", "/GRPART", "/GRQUAD", "/SURF/SURF",
        "/SURF/GRBRIC", "/SURF/BOX", "/SURF/MAT", "/SURF/PROP", "/SURF/SUBSET", "/SURF/PLANE", "/SURF/ELLIPS",
        "/LINE", "/SET",
        // interfaces
        "/INTER/TYPE1", "/INTER/TYPE3", "/INTER/TYPE5", "/INTER/TYPE8", "/INTER/TYPE10", "/INTER/TYPE11",
        "/INTER/TYPE14", "/INTER/TYPE15", "/INTER/TYPE17", "/INTER/TYPE18", "/INTER/TYPE19", "/INTER/TYPE20",
        "/INTER/TYPE21", "/INTER/TYPE23", "/INTER/TYPE24", "/INTER/TYPE25", "/INTER/SUB", "/FRICTION",
        "/DEFAULT", "/INTTHICK",
        // constraints, kinematics, loads, initial state
        "/SKEW/MOV2", "/FRAME/MOV2", "/FRAME/NOD", "/SENSOR", "/RBE2", "/RBE3", "/RLINK", "/CYL_JOINT",
        "/MPC", "/GJOINT", "/BCS/CYCLIC", "/BCS/LAGMUL", "/IMPACC", "/IMPTEMP", "/INIVEL/GRID",
        "/INIVEL/AXIS", "/INIVEL/NODE", "/INIVEL/FVM", "/PFLUID", "/PBLAST", "/LOAD", "/RWALL/LAGMUL",
        "/RWALL/THERM", "/INISHE", "/INIBRI", "/INISH3", "/INITEMP", "/INISTA",
        // physics and model structure
        "/FAIL", "/EOS", "/VISC", "/HEAT", "/MONVOL", "/ALE", "/EULER", "/SPH", "/PARAMETER", "/DEFINE",
        "/TRANSFORM/MATRIX", "/TRANSFORM/POSITION", "/TRANSFORM/AUTOPOSITION", "/INCLUDE", "/ADMAS/2",
        "/ADMAS/3", "/ADMAS/4", "/ADMAS/5", "/ADMAS/6", "/ADMAS/7", "/ADMAS/10", "/DAMP", "/IMPLICIT",
        "/TABLE", "/SECT/PARAL", "/SECT/CIRCLE", "/GAUGE", "/PRELOAD", "/AMS", "/CAA", "/XREF", "/REFSTA",
        "/FUNCT_PYTHON", "/ACTIV", "/LEAK", "/DFS", "/EBCS", "/INIGRAV", "/INIMAP1D", "/INIMAP2D", "/PERTURB",
        "/STATE",
        // time history that radx does not write
        "/TH/MONV", "/TH/SENSOR", "/TH/GAUGE", "/TH/FRAME", "/TH/CLUSTER", "/ATH", "/BTH", "/CTH", "/DTH",
        "/ETH", "/FTH", "/GTH", "/HTH", "/ITH",
        // engine keywords
        "/DT/BRICK/DEL", "/DT/SHELL/DEL", "/DT/SH_3N/DEL", "/DT/SH3N/DEL", "/DT/NODA/STOP", "/DT/NODA/KILL",
        "/DT/NODA/SET", "/DT/AMS", "/ATFILE", "/H3D", "/OUTP", "/DEL", "/KILL", "/CHKPT", "/ANIM/SHELL",
        "/ANIM/BRICK", "/ANIM/MASS", "/DYREL", "/ADYREL", "/IMPL", "/MON/FULL",
        // thermal analysis
        "/CONVEC", "/RADIATION", "/IMPFLUX", "/THERM_STRESS",
        // engine keywords written in a starter deck, and starter options radx lacks
        "/ANIM", "/PRINT", "/PARITH", "/DT", "/RUN", "/STOP", "/RFILE", "/EIG", "/STAMPING", "/NBCS",
        "/CLOAD", "/UPWIND", "/EXTERN", "/NONLOCAL", "/SPHGLO", "/MADYMO", "/INCLUDE_LS-DYNA"};
  }();
  return roots;
}

}  // namespace radx::schema
