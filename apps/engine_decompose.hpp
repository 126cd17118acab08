// radx-engine --decompose P: the decomposition of a model over P ranks, shown without running it. The groups
// go to ranks by METIS (solver/parallel/partition.hpp) or as a group-rank file says (--partition FILE, to cut
// a rigid body or a tie on purpose); the table per rank goes to `out`, and the output folder gets
//   NAME_domain.hdf     the mesh with the cell arrays domain and group and the point array node_owner
//                       (io/hdf5/domain_file.hpp), for ParaView;
//   NAME_partition.txt  the group ranks, in the format --partition reads.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "parser/reading/diagnostics.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/model/model.hpp"

namespace radx::app {

// The group-rank file: a line "GROUP RANK" for every flat element group (0 .. groups - 1, each once, in any
// order), RANK in 0 .. ranks - 1, every rank given at least one group; text from '#' to the end of a line
// and blank lines are skipped. Every problem is added to `diags` (RX807, with the file and line); the ranks
// are valid only without errors.
std::vector<int> read_group_ranks(const std::string& path, std::int64_t groups, int ranks,
                                  Diagnostics& diags);

// The text of a group-rank file for `group_rank`, each line commented with the group's part and first
// element.
std::string group_ranks_text(const model::Model& m, const solver::ElementGroups& groups,
                             const std::vector<int>& group_rank, int ranks, const std::string& root);

// Decomposes, prints and writes (see the header comment). 0 on success, 1 on an input error (printed on
// `err`), with no file of the decomposition left half-written.
int decompose_model(const model::Model& m, const solver::ElementGroups& groups, int ranks,
                    const std::string& partition_file, const std::string& out_dir, const std::string& root,
                    std::ostream& out, std::ostream& err);

}  // namespace radx::app
