// Deck -> Model: resolves every user id to a dense index, checks every reference and value the
// keyword declarations cannot check alone (cross-field and cross-keyword rules), applies two-stage
// defaults (/DEF_SHELL, /DEF_SOLID), builds groups and surfaces, and computes element masses. Every
// problem is reported through Diagnostics with the file:line of the field at fault.
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "parser/reading/deck.hpp"
#include "solver/model/geometry.hpp"
#include "solver/model/model.hpp"

namespace radx {

model::Model build_model(const Deck& deck, Diagnostics& diags);

namespace detail {

// Shared state of the builder steps (one file per keyword family).
class ModelBuilder {
 public:
  ModelBuilder(const Deck& deck, Diagnostics& diags) : deck_(deck), diags_(diags) {}
  model::Model build();

  // -- helpers used by every step
  Where at(SourcePos p, int col = 0) const { return deck_.where(p, col); }
  static About about(const KeywordRecord& r) { return About{r.decl->path, r.id, r.title}; }
  Where at_field(const KeywordRecord& r, std::string_view field) const;
  void error_at(const KeywordRecord& r, std::string_view field, Diag code, std::string msg);
  void warning_at(const KeywordRecord& r, std::string_view field, Diag code, std::string msg);
  void note_at(const KeywordRecord& r, std::string_view field, Diag code, std::string msg);

  using IdIndex = std::unordered_map<std::int64_t, std::int32_t>;
  // Registers an object id; reports a duplicate (RX401) and returns false.
  bool register_id(IdIndex& index, std::int64_t id, std::int32_t dense, const KeywordRecord& r,
                   std::string_view what, std::unordered_map<std::int64_t, SourcePos>& first_pos);
  // Looks up the id held by `field` of `r`; reports RX402 when it does not exist. `optional`: 0 means
  // "none" and returns kNone silently; otherwise 0 is RX404.
  std::int32_t ref(const IdIndex& index, const KeywordRecord& r, std::string_view field,
                   std::string_view what, std::string_view target_keyword, bool optional);

  // -- steps
  void build_nodes();
  void build_materials();
  void read_plas_tab(const KeywordRecord& r, model::Material& mat);   // /MAT/PLAS_TAB's cards
  void read_plas_brit(const KeywordRecord& r, model::Material& mat);  // /MAT/PLAS_BRIT's cards
  model::Material* failure_material(const KeywordRecord& r, std::string_view keyword);  // or nullptr
  void build_failure_models();        // /FAIL/JOHNSON, after the materials
  void resolve_plas_tab_functions();  // after the functions
  void build_fail_tab();              // /FAIL/TAB, after the materials
  void resolve_fail_tab_functions();  // its functions, after the functions
  void build_fail_biquad();           // /FAIL/BIQUAD (build_fail_biquad.cpp)
  void resolve_biquad_strains(const KeywordRecord& r, model::FailBiquad& f);  // C1..C5 after M_Flag
  void resolve_biquad_options(const KeywordRecord& r, model::FailBiquad& f);  // S_Flag, softening
  void resolve_fail_biquad_functions();                                       // its size function
  void read_ogden(const KeywordRecord& r, model::Material& mat);     // /MAT/OGDEN (build_hyperelastic.cpp)
  void read_foam_tab(const KeywordRecord& r, model::Material& mat);  // /MAT/FOAM_TAB (build_foam_tab.cpp)
  void resolve_foam_tab_functions();  // build_foam_tab.cpp: the curves' ids, their checks
  void read_void(const KeywordRecord& r, model::Material& mat);  // /MAT/VOID's optional card
  // RHO_I and RHO_ref (0: RHO_I), shared by the laws whose card starts with them.
  static void read_densities(const KeywordRecord& r, model::Material& mat);
  // E (from `young_field`) and nu with G and K; nu outside [0, 0.5) is an error whose message ends with
  // `nu_consequence` (what the law would do with it).
  void read_isotropic_elastic(const KeywordRecord& r, model::Material& mat, std::string_view young_field,
                              std::string_view nu_consequence);
  void build_rigid_material_bodies();  // build_rigid_materials.cpp: one body per connected /MAT/RIGID set
  void build_properties();
  void build_subsets_and_parts();
  void build_elements();
  void read_spring_property(const KeywordRecord& r, model::Property& p);  // build_springs.cpp
  static void read_beam_property(const KeywordRecord& r, model::BeamProperty& b);
  // Hm and Hf as the deck gives them, else the default of the shell's Ishell (0.1 for 3, 0.01 otherwise).
  static void shell_hourglass_defaults(const KeywordRecord& r, model::ShellProperty& s);
  void read_spring_law(const KeywordRecord& r, model::SpringLaw& s, const std::string& sfx, bool type8);
  void resolve_spring_skews();      // after the skews
  void build_springs();             // after the parts
  void resolve_spring_functions();  // after the functions
  void step_stiffness_from_curve(const KeywordRecord& r, model::SpringLaw& s, const std::string& sfx);
  void check_tetra(model::ElementBlock& b, std::size_t base, const SourcePos& pos, std::int64_t eid);
  void build_boxes();
  void build_functions();
  void build_element_groups();
  void build_groups();
  void build_skews();                // build_skews.cpp
  void apply_random_perturbation();  // build_random.cpp
  void build_surfaces();
  void build_sensors();  // build_loads.cpp, before everything that names a sensor
  void build_loads();
  void build_rigid_walls();
  void build_rigid_bodies();
  void build_sections();  // build_sections.cpp
  void build_time_histories();
  void build_interfaces();
  void build_tied_interfaces();  // /INTER/TYPE2, after the rigid bodies and /BCS
  void build_contact_laws();
  void compute_masses();
  void warn_massless_accelerometers();
  void check_unused_nodes();
  void check_formulations();         // check_formulations.cpp
  void check_truss_and_beam_laws();  // check_formulations.cpp
  void check_line_element_laws(const model::ElementBlock& block,
                               std::string_view what);  // check_formulations.cpp
  void check_ogden_parts();      // build_hyperelastic.cpp: laws 42 and 70 on one-point bricks only
  void check_shell_only_laws();  // check_formulations.cpp: law 27 on shells with points only
  // The transform stage (build_transforms.cpp): submodel transforms right after the elements, node-group
  // transforms after the groups, /MOVE_FUNCT after the functions.
  void transform_submodels();
  void transform_node_groups();
  void reorient_inverted_bricks();
  void move_functions();

  // An affine map x -> A x + b (A row-major).
  struct Affine {
    std::array<double, 9> a{1, 0, 0, 0, 1, 0, 0, 0, 1};
    model::Vec3 b{};
    [[nodiscard]] model::Vec3 apply(const model::Vec3& x) const;
    [[nodiscard]] model::Vec3 linear(const model::Vec3& v) const;
    [[nodiscard]] double det() const;
  };
  bool transform_of(const KeywordRecord& r, const std::function<model::Vec3(std::int32_t)>& where,
                    bool in_submodel, Affine& out);
  // A point or a direction written inside a submodel, in global coordinates (the submodel's transforms, then
  // those of the submodels around it); unchanged at the top level.
  [[nodiscard]] model::Vec3 submodel_point(const KeywordRecord& r, model::Vec3 p) const;
  [[nodiscard]] model::Vec3 submodel_vector(const KeywordRecord& r, model::Vec3 v) const;

  // Group resolution (recursive /GRNOD/GRNOD with loop detection).
  const std::vector<std::int32_t>* group_nodes(std::int32_t g);

  // Element groups (/GRSHEL, /GRSH3N, /GRBRIC) stay in the starter: they are resolved into the surfaces
  // and node groups built from them, and nothing downstream needs them. Each element type has its own
  // group ids, as in Radioss.
  // A brick group holds tetrahedra too, as Radioss groups them with the bricks: its indices past the last
  // brick are tetrahedra (group_element).
  struct ElementGroup {
    const KeywordRecord* record = nullptr;
    model::ElementType type = model::ElementType::Shell4;
    std::vector<std::int32_t> elements;  // sorted, unique indices into the block of `type` (see above)
    std::uint8_t state = 0;              // 0 not built, 1 building, 2 built
  };
  // The group of `type` with user id `id`, or nullptr when there is none.
  const ElementGroup* element_group(model::ElementType type, std::int64_t id) const;
  // Resolves group g (recursive /GRSHEL/GRSHEL and the like, with loop detection); nullptr on a loop.
  const std::vector<std::int32_t>* group_elements(std::int32_t g);
  const model::ElementBlock& block(model::ElementType type) const;
  // The block and index of element e of a group of `type`: a brick group's indices past the bricks are
  // tetrahedra.
  struct GroupElement {
    const model::ElementBlock* block;
    std::int32_t index;
  };
  [[nodiscard]] GroupElement group_element(model::ElementType type, std::int32_t e) const;
  // How many elements a group of `type` can hold: a brick group's bricks and tetrahedra.
  [[nodiscard]] std::size_t group_capacity(model::ElementType type) const;
  // Sets (/SET/GENERAL, /SET/COLLECT; build_sets.cpp). A set holds each kind of member Radioss gives it;
  // it stays in the starter and becomes a node group, a surface or an element group of its id where a
  // keyword names one and no group or surface of that kind has the id (a group of the same id wins, as in
  // Radioss).
  struct SetSegment {
    std::array<std::int32_t, 4> nodes{};
    model::SegmentOwner type = model::SegmentOwner::None;
    std::int32_t owner = model::kNone;
    auto operator<=>(const SetSegment&) const = default;
  };
  struct SetMembers {
    // Sorted, unique dense indices; solids as a brick group holds them (tetrahedra after the bricks).
    std::vector<std::int32_t> nodes, parts, shells, shells3, solids;
    std::vector<SetSegment> segments;  // the surface, in the order its segments were added
  };
  struct Set {
    std::vector<const KeywordRecord*> records;  // one /SET/GENERAL, or every /SET/COLLECT of the id
    bool collect = false;
    SetMembers members;
    std::uint8_t state = 0;   // 0 not built, 1 building, 2 built
    bool had_errors = false;  // its clauses gave errors: an empty set is not warned of again
  };
  void build_sets();  // after the element groups: adds the sets' element groups
  // The members of set s (resolved on first use, SET clauses recursively); nullptr on a loop.
  const SetMembers* set_members(std::int32_t s);
  // The node group or surface of set `id`, built into the model on first use; kNone when no set has it.
  std::int32_t node_group_from_set(std::int64_t id);
  std::int32_t surface_from_set(std::int64_t id);
  // All parts of subset s and of its descendants.
  void subset_parts(std::int32_t s, std::vector<std::int32_t>& out) const;
  std::int32_t node_ref(std::int64_t user_id, const KeywordRecord& r, SourcePos pos, std::string_view what);
  // The user id held by `field` (sensor_ID, sens_ID); RX402 when no sensor has it. 0 = none.
  std::int64_t sensor_ref(const KeywordRecord& r, std::string_view field = "sensor_ID");

  const Deck& deck_;
  Diagnostics& diags_;
  model::Model m_;

  IdIndex mat_ids_, prop_ids_, part_ids_, subset_ids_, box_ids_, funct_ids_, grnod_ids_, surf_ids_,
      inter_ids_, rwall_ids_, rbody_ids_, skew_ids_, sect_ids_, accel_ids_, sensor_ids_;
  // /FRAME/FIX and /FRAME/MOV: in m_.skews with the skews, but apart from skew_ids_ so that a field Radioss
  // reads as a skew only does not accept a frame. The two indexes share one id space.
  IdIndex frame_ids_;
  std::vector<Set> sets_;
  IdIndex set_ids_, collect_set_ids_;  // /SET/GENERAL and /SET/COLLECT ids -> sets_
  std::vector<ElementGroup> element_groups_;
  static constexpr std::size_t kElementTypes = 8;  // model::ElementType's values
  IdIndex element_group_ids_[kElementTypes];       // by model::ElementType
  std::vector<const KeywordRecord*> grnod_records_;
  std::vector<std::uint8_t> grnod_state_;    // 0 not built, 1 building, 2 built
  std::vector<std::uint8_t> node_used_;      // by an element or as a rigid-body / wall node
  std::vector<SourcePos> node_pos_;          // where each node was defined
  std::vector<std::int32_t> node_submodel_;  // the submodel each node was written in (-1: top level)
  std::vector<SourcePos> brick_pos_;         // where each brick was defined
  std::vector<SourcePos> tetra_pos_;         // where each tetrahedron was defined
  IdIndex submodel_ids_;                     // submodel id -> index into deck_.submodels
  std::vector<std::vector<Affine>> submodel_transforms_;  // by submodel, in deck order
  bool mirrored_ = false;               // a transform applied since the last brick check reverses orientation
  std::vector<std::uint8_t> node_bad_;  // 1 when the node's line could not be read
};

}  // namespace detail
}  // namespace radx
