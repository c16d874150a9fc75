// What is derived from a forward problem's state, for the reports, the
// inverse problem and the output: distances to a target, the image's mass
// ratios, stresses, reactions and forces, the validity of a rest shape.
#ifndef restshape_forward_forward_results_h
#define restshape_forward_forward_results_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <restshape/fem/nodal_norms.h>
#include <restshape/forward/forward_problem.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace RestShape
{
  /// Mean and max over the mesh vertices with a target of the distance
  /// (m) between the current position X + d and @p targets (indexed by
  /// triangulation vertex; vertices beyond its size are skipped).
  std::pair<double, double>
  distance_to(const ForwardProblem                &forward,
              const std::vector<dealii::Point<3>> &targets);

  /**
   * Per active cell (by LabelledMesh::cell_index(), from every rank): its
   * mass in the image over its density times its volume in the rest
   * shape X + w, i.e. the mesh's mass ratio times V_mesh / V_rest. What
   * a rest_shape.msh carries (LabelledMesh::mass_ratio()).
   */
  std::vector<double>
  image_mass_ratios(const ForwardProblem &forward);

  /// Element-averaged von Mises Cauchy stress (Pa) of the current state,
  /// one value per active cell (zero on cells not owned here).
  dealii::Vector<float>
  von_mises_stress(const ForwardProblem &forward);

  /// Per active cell (zero on cells not owned here): its volume ratio
  /// J_mean, current over rest volume, and its pressure (Pa, positive in
  /// compression): -U'(J_mean) in the mixed formulation (the condensed
  /// pressure), the element average of -tr(sigma)/3 in the displacement
  /// formulation.
  struct VolumeFields
  {
    dealii::Vector<float> volume_ratio, pressure;
  };
  VolumeFields
  volume_fields(const ForwardProblem &forward);

  /// The smallest det F (volume ratio of the current state to the rest
  /// shape) over all quadrature points, and where ("label 1 at (x, y, z)
  /// mm of the mesh").
  struct Compression
  {
    double      det_F = std::numeric_limits<double>::max();
    std::string where;
  };
  Compression
  most_compressed_cell(const ForwardProblem &forward);

  /// Sum over fixed DoFs of the internal forces: the support reaction (N).
  dealii::Tensor<1, 3>
  support_reaction(const ForwardProblem &forward);

  /// Resultant (N) of the elastic support's tractions on the body.
  dealii::Tensor<1, 3>
  elastic_support_force(const ForwardProblem &forward);

  /// Total external force of @p load (N): the body forces (the weight,
  /// less the buoyancy with Fluid load = buoyancy) plus surface_force().
  dealii::Tensor<1, 3>
  total_external_force(const ForwardProblem &forward, const LoadState &load);

  /// Resultant (N) of the surface loads of @p load at the current state
  /// (the pressure: on the current surface for a follower load, on the
  /// mesh's faces for a dead one; the other face loads), supports left out.
  dealii::Tensor<1, 3>
  surface_force(const ForwardProblem &forward, const LoadState &load);

  /**
   * Check a rest displacement: false (with the number of bad cells) if
   * det(I + grad w) <= 0 at some quadrature point of a cell, i.e. the rest
   * shape has inverted or degenerate cells; then @p where, if given, says
   * where one of them is ("label 1 at (x, y, z) mm of the mesh").
   */
  bool
  rest_shape_is_valid(const Discretization &discretization,
                      const VectorType     &rest,
                      unsigned int         &n_bad,
                      std::string          *where = nullptr);
} // namespace RestShape

#endif
