// What a scene asks of its body, before solving: size, mass and the strains
// the loads impose.
#ifndef restshape_forward_load_scales_h
#define restshape_forward_load_scales_h

#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace RestShape
{
  class ForwardProblem;

  /**
   * The scales of a scene's load on the free body (the cells that are not
   * fully fixed): its bounding box, its height along gravity H, its mass,
   * its volume-weighted Young's modulus E, and the strains
   * rho_b g H / E (rho_b: density less the fluid's, the buoyed weight) and
   * p / E (Surface pressure) that the loads impose. A strain of order one
   * cannot be carried by a co-rotational law without inverting cells.
   */
  struct LoadScales
  {
    dealii::Tensor<1, 3> extent;              // m
    double               height          = 0; // m, along gravity
    double               mass            = 0; // kg, of the whole mesh
    double               E               = 0; // Pa
    double               gravity_strain  = 0;
    double               pressure_strain = 0;

    /// One line: "Body: 140 x 172 x 120 mm, ...".
    std::string
    text() const;
    /// Warnings (empty: none): strains of order one, sizes implausible for
    /// the length unit.
    std::vector<std::string>
    warnings() const;
  };

  /// The load scales of @p forward's scene (after setup()).
  LoadScales
  compute_load_scales(const ForwardProblem &forward);
} // namespace RestShape

#endif
