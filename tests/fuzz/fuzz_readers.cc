// Fuzz targets for every reader of user input (libFuzzer's entry point).
// One source, one target per reader, chosen by RESTSHAPE_FUZZ_TARGET:
//
//   gmsh vtk vtu abaqus   Mesh/File (.msh, .vtk, .vtu, .inp)
//   off stl obj           Contact/Obstacle file
//   prm                   a scene file (with includes) and its parameters
//   nifti                 a labelled NIfTI image (restshape-mesh --image)
//
// The contract: a reader either returns what it promises (finite
// coordinates, cells that refer to existing vertices, labels in range) or
// throws InputError; anything else (another exception, a crash, a
// sanitizer report, a hang) is a finding. The input is written to a file
// with the reader's extension, because every reader takes a path.
#include <restshape/app/parameters.h>
#include <restshape/app/scene_input.h>
#include <restshape/base/input_error.h>
#include <restshape/base/label_values.h>
#include <restshape/mesh/mesh_formats.h>

#ifdef RESTSHAPE_FUZZ_OBSTACLE
#  include <restshape/contact/obstacle.h>
#endif
#ifdef RESTSHAPE_FUZZ_NIFTI
#  include <restshape/mesher/labelled_image.h>
#endif

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
  using namespace RestShape;

  [[noreturn]] void
  finding(const std::string &what)
  {
    std::cerr << "FINDING: " << what << std::endl;
    std::abort();
  }

  /// The input as a file named with @p extension (one per process).
  std::string
  as_file(const uint8_t *data, const size_t size, const std::string &extension)
  {
    const std::string path =
      "/tmp/restshape-fuzz-" + std::to_string(getpid()) + "." + extension;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), size);
    return path;
  }

  [[maybe_unused]] void
  check_mesh(const MeshDescription &mesh)
  {
    for (const auto &v : mesh.vertices)
      for (unsigned int d = 0; d < 3; ++d)
        if (!std::isfinite(v[d]))
          finding("a vertex coordinate is not finite");
    for (const auto &t : mesh.targets)
      for (unsigned int d = 0; d < 3; ++d)
        if (!std::isfinite(t[d]))
          finding("a target position is not finite");
    for (const double m : mesh.mass_ratios)
      if (!(m > 0) || !std::isfinite(m))
        finding("a mass ratio is not a positive finite number");
    for (const auto &cell : mesh.cells)
      {
        for (const unsigned int v : cell.vertices)
          if (v >= mesh.vertices.size())
            finding("a cell refers to a vertex that does not exist");
        if (static_cast<long>(cell.material_id) > max_label)
          finding("a label beyond max_label");
      }
  }

  void
  run(const std::string &file)
  {
#if defined(RESTSHAPE_FUZZ_MESH)
    check_mesh(read_mesh(file, 1e-3, "Mesh/File"));
#elif defined(RESTSHAPE_FUZZ_OBSTACLE)
    Obstacle obstacle(file, 1e-3, true);
    if (!(obstacle.n_triangles() > 0))
      finding("an obstacle without triangles");
#elif defined(RESTSHAPE_FUZZ_PRM)
    dealii::ParameterHandler prm;
    Parameters::declare_parameters(prm);
    read_scene(prm, file, {});
    Parameters parameters;
    parameters.parse_parameters(prm);
#elif defined(RESTSHAPE_FUZZ_NIFTI)
    const LabelledImage image = read_labelled_image(file, "--image");
    (void)image.max_label();
#endif
  }
} // namespace

extern "C" int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const std::string file = as_file(data, size, RESTSHAPE_FUZZ_EXTENSION);
  try
    {
      run(file);
    }
  catch (const InputError &)
    {
      // The contract: one clear error.
    }
  catch (const std::exception &e)
    {
      finding(std::string("not an InputError: ") + e.what());
    }
  catch (...)
    {
      finding("an exception that is not a std::exception");
    }
  std::remove(file.c_str());
  return 0;
}
