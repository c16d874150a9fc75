// Study mode's comparison of runs: each run's fields against a reference
// run, at the mesh positions they share.
#ifndef restshape_app_study_compare_h
#define restshape_app_study_compare_h

#include <optional>
#include <string>
#include <vector>

namespace RestShape
{
  /// How far a run's fields are from the reference run's.
  struct FieldDifference
  {
    /// max |u - u_ref| / max |u_ref| over the shared nodes (u: the
    /// displacement from the rest shape), and the same for the shift from
    /// the mesh to the rest shape (inverse runs); empty where not known.
    std::optional<double> displacement, rest_shape;
    /// Nodes at the same mesh position in both runs.
    unsigned int shared_nodes = 0;
  };

  /**
   * The differences of the runs whose nodes.csv files are @p files (one per
   * run; "" for a run without one) from run @p reference. Nodes are matched
   * by mesh position (to 1e-6 of the mesh's length unit): the vertices of a
   * coarse mesh are nodes of every refinement of it and of its P2 and Q2
   * spaces, so orders and refinements of one mesh share them. The
   * reference itself gets no difference.
   */
  std::vector<FieldDifference>
  differences_to_reference(const std::vector<std::string> &files,
                           const std::size_t               reference);
} // namespace RestShape

#endif
