// Study mode (restshape --study): every combination of parameter values.
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <fcntl.h>
#include <restshape/app/parameters.h>
#include <restshape/app/scene_input.h>
#include <restshape/app/study.h>
#include <restshape/app/study_compare.h>
#include <restshape/app/study_plot.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_names.h>
#include <restshape/forward/registered_parameters.h>
#include <restshape/io/output.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

extern char **environ;

namespace RestShape
{
  using namespace dealii;

  StudyAxis
  StudyAxis::parse(const std::string &text)
  {
    const auto equal = text.find('=');
    StudyAxis  axis;
    if (equal != std::string::npos)
      {
        axis.parameter = Utilities::trim(text.substr(0, equal));
        for (const std::string &v :
             Utilities::split_string_list(text.substr(equal + 1), ','))
          if (!v.empty())
            axis.values.push_back(v);
      }
    if (axis.parameter.empty() || axis.values.empty())
      throw InputError(
        "",
        "--study",
        "got '" + text +
          "'; expected 'Subsection/Parameter=value1,value2,...'");
    return axis;
  }

  namespace
  {
    /// One run of the study.
    struct StudyRun
    {
      std::vector<std::string> values;
      std::string              folder;
      int                      exit_code = 0;
      /// Why it failed, in one line ("" after a success): summary.json's
      /// failure, else the program's error line, else the signal.
      std::string                 reason;
      double                      seconds   = 0;
      double                      memory_mb = 0;
      boost::property_tree::ptree summary;

      std::optional<double>
      number(const std::string &key) const
      {
        const auto v = summary.get_optional<double>(key);
        return v ? std::optional<double>(*v) : std::nullopt;
      }
    };

    /// Every combination of the axes' values, the last axis fastest.
    std::vector<std::vector<std::string>>
    combinations(const std::vector<StudyAxis> &axes)
    {
      std::vector<std::vector<std::string>> result = {{}};
      for (const StudyAxis &axis : axes)
        {
          std::vector<std::vector<std::string>> next;
          for (const auto &prefix : result)
            for (const std::string &v : axis.values)
              {
                next.push_back(prefix);
                next.back().push_back(v);
              }
          result = next;
        }
      return result;
    }

    /// "03_Polynomial-degree-2_Global-refinements-1".
    std::string
    folder_name(const unsigned int              index,
                const std::vector<StudyAxis>   &axes,
                const std::vector<std::string> &values)
    {
      std::ostringstream name;
      name << std::setw(2) << std::setfill('0') << index + 1;
      for (unsigned int a = 0; a < axes.size(); ++a)
        {
          const std::string &p = axes[a].parameter;
          std::string entry    = p.substr(p.rfind('/') + 1) + "-" + values[a];
          for (char &c : entry)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' &&
                c != '-')
              c = '-';
          name << '_' << entry;
        }
      return name.str();
    }

    /// While a run goes on, a progress line this often (s).
    constexpr double heartbeat_seconds = 60;

    /// A signal that arrived during the study (0: none): passed on to
    /// the run in progress, then the study ends with 128 + it.
    volatile std::sig_atomic_t study_signal = 0;

    extern "C" void
    on_study_signal(const int sig)
    {
      study_signal = sig;
    }

    void
    install_study_signal_handlers()
    {
      struct sigaction action;
      std::memset(&action, 0, sizeof(action));
      action.sa_handler = on_study_signal;
      sigemptyset(&action.sa_mask);
      for (const int sig : {SIGINT, SIGTERM, SIGHUP})
        sigaction(sig, &action, nullptr);
    }

    /// The last line of @p log that says "error:" ("" if none).
    std::string
    error_line(const std::string &log)
    {
      std::ifstream in(log);
      std::string   line, last;
      while (std::getline(in, line))
        if (line.find("error:") != std::string::npos)
          last = line;
      return last;
    }

    /// The last non-empty line of the file @p log ("" if none).
    std::string
    last_line(const std::string &log)
    {
      std::ifstream in(log);
      std::string   line, last;
      while (std::getline(in, line))
        if (!line.empty())
          last = line;
      return last;
    }

    /// Run @p program with @p args, stdout and stderr to @p log; its exit
    /// code, wall seconds and peak memory (MB). Every heartbeat_seconds,
    /// the run's last line of screen output, prefixed with @p name.
    void
    spawn(const std::string              &program,
          const std::vector<std::string> &args,
          const std::string              &log,
          const std::string              &name,
          StudyRun                       &run)
    {
      std::vector<char *> argv = {const_cast<char *>(program.c_str())};
      for (const std::string &a : args)
        argv.push_back(const_cast<char *>(a.c_str()));
      argv.push_back(nullptr);
      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      posix_spawn_file_actions_addopen(
        &actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      posix_spawn_file_actions_adddup2(&actions, 1, 2);
      const auto start = std::chrono::steady_clock::now();
      const auto since = [&start]() {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                             start)
          .count();
      };
      pid_t     pid   = 0;
      const int error = posix_spawn(
        &pid, program.c_str(), &actions, nullptr, argv.data(), environ);
      posix_spawn_file_actions_destroy(&actions);
      if (error != 0)
        throw InputError("", "--study", "cannot start " + program);
      int           status = 0;
      struct rusage usage;
      double        next_report = heartbeat_seconds;
      while (wait4(pid, &status, WNOHANG, &usage) == 0)
        {
          if (study_signal != 0)
            {
              // The run ends with the study, never as an orphan.
              ::kill(pid, study_signal);
              wait4(pid, &status, 0, &usage);
              break;
            }
          std::this_thread::sleep_for(std::chrono::milliseconds(200));
          if (since() < next_report)
            continue;
          std::cout << "  " << name << ": running for " << std::fixed
                    << std::setprecision(0) << since() << std::defaultfloat
                    << " s: " << last_line(log) << std::endl;
          next_report += heartbeat_seconds;
        }
      run.seconds   = since();
      run.memory_mb = usage.ru_maxrss / 1024.;
      if (WIFSIGNALED(status))
        {
          run.exit_code = 128 + WTERMSIG(status);
          run.reason    = std::string("killed by signal ") +
                       std::to_string(WTERMSIG(status)) + " (" +
                       strsignal(WTERMSIG(status)) + ")";
        }
      else
        run.exit_code = WEXITSTATUS(status);
    }

    /// The run's reason, once its summary is read.
    void
    find_reason(StudyRun &run, const std::string &log)
    {
      if (run.exit_code == 0 || !run.reason.empty())
        return;
      const std::string line = error_line(log);
      run.reason             = !line.empty() ?
                                 line :
                                 run.summary.get<std::string>("failure", "no error line");
    }

    /// The columns of @p keys that some run reports.
    std::vector<std::string>
    reported(const std::vector<StudyRun>    &runs,
             const std::vector<std::string> &keys)
    {
      std::vector<std::string> result;
      for (const std::string &key : keys)
        for (const StudyRun &run : runs)
          if (run.number(key))
            {
              result.push_back(key);
              break;
            }
      return result;
    }

    /// Errors against an exact solution (Verification), finest first.
    const std::vector<std::string> exact_error_keys = {"rest_l2_error_relative",
                                                       "rest_h1_error_relative",
                                                       "l2_error_relative",
                                                       "h1_error_relative"};

    /// The reference of the comparison: the converged run with the most
    /// DoFs (the last of equals).
    std::size_t
    finest_run(const std::vector<StudyRun> &runs)
    {
      std::size_t finest = runs.size();
      for (std::size_t r = 0; r < runs.size(); ++r)
        if (runs[r].summary.get<bool>("converged", false) &&
            (finest == runs.size() ||
             runs[r].number("n_dofs").value_or(0) >=
               runs[finest].number("n_dofs").value_or(0)))
          finest = r;
      return finest;
    }

    /// Whether the run warned that its displacement formulation locks
    /// (summary.json's formulation_warning).
    bool
    locks(const StudyRun &run)
    {
      return !run.summary.get<std::string>("formulation_warning", "").empty();
    }

    /// "converged, 3597 DoFs, 4 Newton steps (+ 4 of the direct inverse,
    /// 13 Jacobian products), 0.52 s, 187 MB"
    std::string
    run_figures(const StudyRun &run, const std::string &out)
    {
      std::ostringstream text;
      text << std::setprecision(3);
      if (run.exit_code != 0)
        text << "FAILED (exit code " << run.exit_code << ": " << run.reason
             << "; see " << out << "/screen.log), ";
      else
        text << (run.summary.get<bool>("converged", false) ? "converged, " :
                                                             "done, ");
      text << long(run.number("n_dofs").value_or(0)) << " DoFs, "
           << long(run.number("newton_iterations").value_or(0))
           << " Newton steps";
      if (const auto direct = run.number("direct_inverse_newton_steps"))
        text << " (+ " << long(*direct) << " of the direct inverse, "
             << long(run.number("direct_inverse_jacobian_products").value_or(0))
             << " Jacobian products)";
      if (const auto it = run.number("inverse_iterations"))
        text << ", " << long(*it) << " inverse iterations";
      text << ", " << run.seconds << " s, " << run.memory_mb << " MB";
      if (locks(run))
        text << "; warned: the displacement formulation locks at this "
                "Poisson's ratio";
      return text.str();
    }
  } // namespace

  void
  write_study_tables(const std::vector<StudyAxis> &axes,
                     const std::vector<StudyRun>  &runs,
                     const std::string            &directory);

  int
  run_study(const std::string              &program,
            const std::string              &prm_file,
            const std::vector<std::string> &overrides,
            const std::vector<StudyAxis>   &axes)
  {
    // Check the scene and every value before the first run.
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    read_scene(prm, prm_file, overrides);
    prm.enter_subsection("Output");
    const std::string directory = prm.get("Directory") + "/study";
    prm.leave_subsection();
    for (const StudyAxis &axis : axes)
      for (const std::string &v : axis.values)
        apply_override(prm, axis.parameter + "=" + v, "--study");
    ensure_writable_directory(directory, "Output/Directory");
    claim_directory(directory, "Output/Directory");
    install_study_signal_handlers();

    const auto            all = combinations(axes);
    std::vector<StudyRun> runs;
    int                   worst = 0;
    for (unsigned int i = 0; i < all.size(); ++i)
      {
        StudyRun run;
        run.values            = all[i];
        run.folder            = folder_name(i, axes, all[i]);
        const std::string out = directory + "/" + run.folder;
        std::filesystem::create_directories(out);
        // An earlier study's results there are never read as this run's.
        remove_previous_results(out);
        std::vector<std::string> args;
        for (const std::string &o : overrides)
          args.insert(args.end(), {"--set", o});
        std::string described;
        for (unsigned int a = 0; a < axes.size(); ++a)
          {
            args.insert(args.end(),
                        {"--set", axes[a].parameter + "=" + all[i][a]});
            described += (a ? ", " : "") + axes[a].parameter + "=" + all[i][a];
          }
        // The nodes' fields, for the comparison of the runs.
        args.insert(args.end(),
                    {"--set",
                     "Output/Write nodal CSV=true",
                     "--set",
                     "Output/Directory=" + out,
                     prm_file});
        const std::string name = "study run " + std::to_string(i + 1) + "/" +
                                 std::to_string(all.size());
        std::cout << name << " started: " << described
                  << " (screen output: " << out << "/screen.log)" << std::endl;
        spawn(program, args, out + "/screen.log", name, run);
        try
          {
            boost::property_tree::read_json(out + "/summary.json", run.summary);
          }
        catch (const std::exception &)
          {
            // A run that stopped before its summary: its exit code says so.
          }
        find_reason(run, out + "/screen.log");
        std::cout << name << " finished: " << run_figures(run, out)
                  << std::endl;
        worst = std::max(worst, run.exit_code);
        runs.push_back(run);
        if (study_signal != 0)
          {
            write_study_tables(axes, runs, directory);
            std::cout << "study: stopped by signal " << int(study_signal)
                      << " after " << runs.size() << " of " << all.size()
                      << " runs (the last one stopped with it)" << std::endl;
            return 128 + study_signal;
          }
      }
    write_study_tables(axes, runs, directory);
    std::cout << "study: " << runs.size() << " runs; " << directory
              << "/study.csv, study.txt, study_error_vs_time.svg" << std::endl;
    return worst;
  }

  namespace
  {
    /// A CSV field: quoted (quotes doubled) if it holds a comma or quote.
    std::string
    csv_field(const std::string &text)
    {
      if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
      std::string quoted = "\"";
      for (const char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
      return quoted + "\"";
    }
  } // namespace

  void
  write_study_tables(const std::vector<StudyAxis> &axes,
                     const std::vector<StudyRun>  &runs,
                     const std::string            &directory)
  {
    const std::vector<std::string> errors = reported(runs, exact_error_keys);
    const std::vector<std::string> costs =
      reported(runs,
               {"newton_iterations",
                "direct_inverse_newton_steps",
                "direct_inverse_jacobian_products",
                "inverse_iterations"});
    const std::vector<std::string> inverse_errors =
      reported(runs, {"mean_error_mm", "max_error_mm"});
    // Each run against the finest one, at the nodes they share.
    const std::size_t        finest = finest_run(runs);
    std::vector<std::string> csv_files;
    for (const StudyRun &run : runs)
      csv_files.push_back(
        std::filesystem::exists(directory + "/" + run.folder + "/nodes.csv") ?
          directory + "/" + run.folder + "/nodes.csv" :
          "");
    const std::vector<FieldDifference> difference =
      differences_to_reference(csv_files, finest);
    bool any_rest = false;
    for (const FieldDifference &d : difference)
      any_rest = any_rest || d.rest_shape.has_value();

    TableHandler                          table;
    std::vector<std::string>              header = {"run"};
    std::vector<std::vector<std::string>> rows;
    for (const StudyAxis &axis : axes)
      header.push_back(axis.parameter.substr(axis.parameter.rfind('/') + 1));
    header.insert(
      header.end(),
      {"exit_code", "converged", "n_dofs", "formulation", "locking_warning"});
    header.insert(header.end(), costs.begin(), costs.end());
    header.insert(header.end(), errors.begin(), errors.end());
    header.insert(header.end(), inverse_errors.begin(), inverse_errors.end());
    header.insert(header.end(),
                  {"max_displacement_mm", "displacement_difference_to_finest"});
    if (any_rest)
      header.push_back("rest_shape_difference_to_finest");
    header.insert(header.end(), {"wall_seconds", "peak_memory_MB", "reason"});
    const auto text = [](const std::optional<double> &x) {
      if (!x)
        return std::string("-");
      std::ostringstream s;
      s << std::setprecision(6) << *x;
      return s.str();
    };
    for (unsigned int r = 0; r < runs.size(); ++r)
      {
        const StudyRun          &run = runs[r];
        std::vector<std::string> row = {run.folder};
        row.insert(row.end(), run.values.begin(), run.values.end());
        row.push_back(std::to_string(run.exit_code));
        row.push_back(run.summary.get<std::string>("converged", "false"));
        row.push_back(text(run.number("n_dofs")));
        row.push_back(run.summary.get<std::string>("formulation", "-"));
        row.push_back(locks(run) ? "true" : "false");
        for (const auto *keys : {&costs, &errors, &inverse_errors})
          for (const std::string &key : *keys)
            row.push_back(text(run.number(key)));
        row.push_back(text(run.number("max_displacement_mm")));
        row.push_back(r == finest ? "reference" :
                                    text(difference[r].displacement));
        if (any_rest)
          row.push_back(r == finest ? "reference" :
                                      text(difference[r].rest_shape));
        row.push_back(text(run.seconds));
        row.push_back(text(run.memory_mb));
        row.push_back(run.reason.empty() ? "-" : run.reason);
        for (unsigned int c = 0; c < header.size(); ++c)
          table.add_value(header[c], row[c]);
        rows.push_back(row);
      }
    write_file_atomically(
      directory + "/study.csv",
      [&](std::ostream &out) {
        for (unsigned int c = 0; c < header.size(); ++c)
          out << (c ? "," : "") << header[c];
        out << '\n';
        for (const auto &row : rows)
          {
            for (unsigned int c = 0; c < row.size(); ++c)
              out << (c ? "," : "") << csv_field(row[c]);
            out << '\n';
          }
      },
      "Output/Directory");
    write_file_atomically(
      directory + "/study.txt",
      [&](std::ostream &out) {
        table.write_text(out, TableHandler::org_mode_table);
      },
      "Output/Directory");
    // Plot the first exact error, else the difference to the finest run
    // (of the rest shape in inverse runs).
    std::string name = any_rest ? "rest shape difference to the finest run" :
                                  "displacement difference to the finest run";
    std::vector<std::optional<double>> plotted;
    for (unsigned int r = 0; r < runs.size(); ++r)
      plotted.push_back(!errors.empty() ? runs[r].number(errors[0]) :
                        any_rest        ? difference[r].rest_shape :
                                          difference[r].displacement);
    if (!errors.empty())
      name = errors[0];
    std::vector<StudyPoint> points;
    for (unsigned int r = 0; r < runs.size(); ++r)
      if (plotted[r])
        points.push_back({runs[r].seconds, *plotted[r], runs[r].folder});
    write_log_log_plot(points,
                       "wall time (s)",
                       name,
                       directory + "/study_error_vs_time.svg");
  }
} // namespace RestShape
