// restshape: command line front end.
//
//   restshape SCENE.prm                     run a scene
//   restshape --set 'Sub/Param=value' ...   override parameters (repeatable)
//   restshape --print-parameters [SUBSECTION]  parameters with defaults
//   restshape --print-load-terms               the load terms, described
//   restshape --study 'Sub/Param=v1,v2' ... SCENE.prm  every combination
//
// Exit codes: 0 success, 1 bad input, 2 a solver did not converge,
// 3 internal error.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <restshape/app/parameters.h>
#include <restshape/app/scene_input.h>
#include <restshape/app/simulator.h>
#include <restshape/app/study.h>
#include <restshape/base/input_error.h>
#include <restshape/base/interruption.h>
#include <restshape/base/mpi_start.h>
#include <restshape/base/parameter_names.h>
#include <restshape/base/progress.h>
#include <restshape/base/version.h>
#include <restshape/forward/registered_parameters.h>
#include <restshape/loads/load_registry.h>
#include <restshape/mesh/labelled_mesh.h>
#include <restshape/solver/linear_solver.h>

#include <filesystem>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace RestShape;

namespace
{
  const char *usage =
    "usage: restshape [--set 'Subsection/Parameter=value']... SCENE.prm\n"
    "       restshape --print-parameters [SUBSECTION]\n"
    "       restshape --print-load-terms\n"
    "       restshape --version\n"
    "       restshape --study 'Subsection/Parameter=value1,value2,...'...\n"
    "                 [--set 'Subsection/Parameter=value']... SCENE.prm\n"
    "\n"
    "--study runs the scene once per combination of the values of every\n"
    "--study parameter, each in OUTPUT/study/NN_.../ (OUTPUT: the scene's\n"
    "Output/Directory), and writes OUTPUT/study/study.csv and study.txt\n"
    "(DoFs, Newton and inverse iterations, errors, wall time and peak\n"
    "memory per run) and study_error_vs_time.svg (doc/model.md, Study\n"
    "mode).\n";

  /// Every parameter, or those of the top-level subsection @p only.
  void
  print_parameters(const ParameterHandler &prm, const std::string &only)
  {
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::PRM);
    if (only.empty())
      {
        std::cout << text.str();
        return;
      }
    std::istringstream in(text.str());
    bool               inside = false;
    for (std::string line; std::getline(in, line);)
      {
        inside = inside || line == "subsection " + only;
        if (inside)
          std::cout << line << '\n';
        if (inside && line == "end")
          break;
      }
  }
  /// Whether the command line asks for a study (--study anywhere).
  bool
  wants_study(const int argc, char **argv)
  {
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]).rfind("--study", 0) == 0)
        return true;
    return false;
  }

  /// restshape --study ...: parsed and run without MPI (the runs are
  /// processes of their own).
  int
  study_main(const int argc, char **argv)
  {
    std::string prm_file;
    try
      {
        std::vector<StudyAxis>   axes;
        std::vector<std::string> overrides;
        for (int i = 1; i < argc; ++i)
          {
            const std::string arg = argv[i];
            if ((arg == "--study" || arg == "--set") && i + 1 >= argc)
              throw InputError("", arg, "missing value after the option");
            if (arg == "--study")
              axes.push_back(StudyAxis::parse(argv[++i]));
            else if (arg.rfind("--study=", 0) == 0)
              axes.push_back(StudyAxis::parse(arg.substr(8)));
            else if (arg == "--set")
              overrides.emplace_back(argv[++i]);
            else if (arg.rfind("--set=", 0) == 0)
              overrides.push_back(arg.substr(6));
            else if (!arg.empty() && arg[0] == '-')
              throw InputError(arg, "", "unknown option with --study");
            else if (prm_file.empty())
              prm_file = arg;
            else
              throw InputError(arg, "", "more than one scene file given");
          }
        if (prm_file.empty())
          throw InputError("", "--study", "no scene file given");
        return run_study(std::filesystem::read_symlink("/proc/self/exe"),
                         prm_file,
                         overrides,
                         axes);
      }
    catch (const InputError &exc)
      {
        const InputError e = exc.file.empty() ? exc.in_file(prm_file) : exc;
        std::cerr << "restshape: error: " << e.what() << std::endl;
        return 1;
      }
    catch (const std::exception &exc)
      {
        std::cerr << "restshape: internal error: " << one_line_message(exc)
                  << std::endl;
        return 3;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  if (wants_study(argc, argv))
    return study_main(argc, argv);
  prefer_fast_singleton_mpi();
  Utilities::MPI::MPI_InitFinalize mpi(argc,
                                       argv,
                                       numbers::invalid_unsigned_int);
  set_blas_threads_for(no_factorisation);
  install_interrupt_handlers();
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
  // A line at least every few seconds, whatever runs (doc/model.md).
  const ProgressHeartbeat heartbeat(root, progress_silence_from_environment());
  std::string             prm_file;

  try
    {
      ParameterHandler prm;
      Parameters::declare_parameters(prm);

      std::vector<std::string> overrides;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--print-parameters")
            {
              const std::string only =
                i + 1 < argc && argv[i + 1][0] != '-' ? argv[i + 1] : "";
              if (!only.empty())
                ParameterNames(prm).check_top_subsection(only);
              if (root)
                print_parameters(prm, only);
              return 0;
            }
          else if (arg == "--print-load-terms")
            {
              if (root)
                std::cout << load_terms_reference();
              return 0;
            }
          else if (arg == "--help" || arg == "-h")
            {
              if (root)
                std::cout << usage;
              return 0;
            }
          else if (arg == "--version")
            {
              if (root)
                std::cout << version_text("restshape") << std::endl;
              return 0;
            }
          else if (arg == "--set")
            {
              if (i + 1 >= argc)
                throw InputError("--set",
                                 "",
                                 "missing 'Subsection/Parameter=value'");
              overrides.emplace_back(argv[++i]);
            }
          else if (arg.rfind("--set=", 0) == 0)
            overrides.push_back(arg.substr(6));
          else if (!arg.empty() && arg[0] == '-')
            throw InputError(arg, "", "unknown option; see restshape --help");
          else if (prm_file.empty())
            prm_file = arg;
          else
            throw InputError(arg, "", "more than one scene file given");
        }
      if (prm_file.empty())
        throw InputError(
          "",
          "",
          "no scene file given; usage: restshape [--set 'Subsection/Parameter=value']... SCENE.prm");
      const std::vector<std::string> scenarios =
        read_scene(prm, prm_file, overrides);

      // Names of labels (the mesh's, Mesh/Label names) become labels.
      MeshParameters mesh_parameters;
      mesh_parameters.parse_parameters(prm);
      Parameters::replace_label_names(prm, scene_label_names(mesh_parameters));
      Parameters parameters;
      parameters.parse_parameters(prm, scenarios);
      // Destroy the simulator (and its TimerOutput, which prints a banner
      // when destroyed during stack unwinding) before reporting an error.
      std::exception_ptr error;
      {
        Simulator simulator(parameters, prm, prm_file, comm);
        try
          {
            simulator.run();
          }
        catch (...)
          {
            error = std::current_exception();
          }
      }
      if (error)
        std::rethrow_exception(error);
      if (!std::cout.good())
        {
          if (root)
            std::cerr << "restshape: error: " << prm_file
                      << ": the screen output could not be written (stdout "
                         "was closed: broken pipe); the results in "
                      << parameters.output.directory
                      << " are complete (summary.json: screen_output)"
                      << std::endl;
          return 5;
        }
    }
  catch (const InputError &exc)
    {
      const InputError e = exc.file.empty() ? exc.in_file(prm_file) : exc;
      if (root)
        std::cerr << "restshape: error: " << e.what() << std::endl;
      return 1;
    }
  catch (const SolverFailure &exc)
    {
      if (root)
        std::cerr << "restshape: error: " << prm_file << ": " << exc.what()
                  << std::endl;
      return 2;
    }
  catch (const OutputFailure &exc)
    {
      if (root)
        std::cerr << "restshape: error: " << prm_file << ": " << exc.what()
                  << "; the partial results are removed" << std::endl;
      return 5;
    }
  catch (const ScenarioFailure &exc)
    {
      if (root)
        std::cerr << "restshape: error: " << prm_file << ": " << exc.what()
                  << std::endl;
      return 4;
    }
  catch (const std::exception &exc)
    {
      if (root)
        std::cerr << "restshape: internal error: " << prm_file << ": "
                  << one_line_message(exc) << std::endl;
      return 3;
    }
  return 0;
}
