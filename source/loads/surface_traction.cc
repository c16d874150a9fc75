#include <deal.II/base/mpi.h>

#include <restshape/base/input_error.h>
#include <restshape/loads/surface_traction.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    const std::string section = "Surface traction";
  } // namespace

  namespace
  {
    void
    declare(ParameterHandler &prm)
    {
      prm.enter_subsection(section);
      prm.declare_entry("Traction",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "A dead traction in Pa (force per unit area of the "
                        "mesh's faces, x, y, z in the mesh's axes) on the "
                        "boundary faces of Labels whose centres lie in Region, "
                        "e.g. a retractor's spatula. It scales with the load "
                        "like gravity. Zero: none.");
      prm.declare_entry("Labels",
                        "",
                        Patterns::Anything(),
                        "Labels whose boundary faces carry the traction; "
                        "empty: every label not fully fixed.");
      prm.declare_entry("Region",
                        "",
                        Patterns::Anything(),
                        "Where the loaded faces' centres lie, in the mesh's "
                        "length unit: 'sphere: x, y, z, r', 'cylinder: x, y, "
                        "z, ax, ay, az, r' or 'box: x0, y0, z0, x1, y1, z1' "
                        "(two opposite corners); empty: every face of "
                        "Labels.");
      prm.leave_subsection();
    }

    LoadTermFactory
    parse(ParameterHandler &prm, double)
    {
      SurfaceTraction::Settings s;
      prm.enter_subsection(section);
      s.traction = parse_vector(prm.get("Traction"), section + "/Traction");
      s.labels   = parse_label_set(prm.get("Labels"), section + "/Labels");
      s.region   = parse_region(prm.get("Region"), section + "/Region");
      prm.leave_subsection();
      if (s.region.shape == Region::Shape::surface)
        throw InputError("",
                         section + "/Region",
                         "a surface file cannot bound the loaded patch; "
                         "expected 'sphere: x, y, z, r', 'cylinder: x, y, z, "
                         "ax, ay, az, r' or 'box: x0, y0, z0, x1, y1, z1'");
      if (s.traction.norm() == 0)
        return {};
      return [s](const LoadContext &context) {
        return std::make_unique<SurfaceTraction>(s, context);
      };
    }
  } // namespace

  LoadTermInfo
  SurfaceTraction::info()
  {
    LoadTermInfo i;
    i.name        = section;
    i.description = "A dead traction on a patch of the surface (a "
                    "retractor's spatula, a hand pressing on the tissue): "
                    "subsection Surface traction, on the boundary faces of "
                    "its labels whose centres lie in its region. Enabled by "
                    "a traction other than zero.";
    i.loads       = {section};
    i.declare     = declare;
    i.parse       = parse;
    i.labels      = {{section, "Labels", false}};
    return i;
  }

  void
  SurfaceTraction::scene_load(LoadState &load) const
  {
    load.add(section, {});
  }

  SurfaceTraction::SurfaceTraction(const Settings    &settings,
                                   const LoadContext &context)
    : traction(settings.traction)
    , labels(context.labels_or_unfixed(settings.labels))
    , region(settings.region)
    , context(context)
  {
    region.scale(context.mesh.length_unit());
    unsigned int    faces = 0;
    FEFaceValues<3> fv(context.mapping,
                       context.fe,
                       context.face_quadrature,
                       update_JxW_values);
    for_each_boundary_face(
      context.dof_handler, context.mesh, labels, [&](const auto &cell, auto f) {
        if (!loaded(cell, f))
          return;
        ++faces;
        fv.reinit(cell, f);
        for (const unsigned int q : fv.quadrature_point_indices())
          area += fv.JxW(q);
      });
    if (Utilities::MPI::sum(faces, context.comm) == 0)
      throw InputError("",
                       section + "/Region",
                       "no boundary face of the loaded labels has its "
                       "centre in the region; expected a region that "
                       "meets the surface");
  }

  bool
  SurfaceTraction::loaded(const CellIterator &cell, const unsigned int f) const
  {
    return cell->face(f)->at_boundary() && labels.count(cell->material_id()) &&
           (!region.defined() || region.contains(cell->face(f)->center()));
  }

  void
  SurfaceTraction::assemble_faces(const LoadCell &c) const
  {
    const double weight = c.load.weight(section);
    if (weight == 0)
      return;
    const FESystem<3> &fe = context.fe;
    const Tensor<1, 3> t  = weight * traction;
    for (const unsigned int f : c.cell->face_indices())
      if (loaded(c.cell, f))
        {
          const FaceScratch &fv = c.face(f);
          for (const unsigned int q : fv.quadrature_point_indices())
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              {
                const double f_ext = fv.shape_value(i, q) *
                                     t[fe.system_to_component_index(i).first] *
                                     fv.JxW(q);
                c.cell_external(i) += f_ext;
                c.cell_rhs(i) += f_ext;
              }
        }
  }

  Tensor<1, 3>
  SurfaceTraction::local_resultant(const LoadState &load,
                                   const VectorType &,
                                   const VectorType &) const
  {
    // A dead traction on the mesh's faces: its resultant is fixed.
    return load.weight(section) * area * traction;
  }
} // namespace RestShape
