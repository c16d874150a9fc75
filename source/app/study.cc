// Study mode (restshape --study): every combination of parameter values.
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <fcntl.h>
#include <restshape/app/scene_input.h>
#include <restshape/app/study.h>
#include <restshape/app/study_plot.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/parameter_names.h>
#include <restshape/base/parameters.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

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
      std::vector<std::string>    values;
      std::string                 folder;
      int                         exit_code = 0;
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

    /// Run @p program with @p args, stdout and stderr to @p log; its exit
    /// code, wall seconds and peak memory (MB).
    void
    spawn(const std::string              &program,
          const std::vector<std::string> &args,
          const std::string              &log,
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
      pid_t      pid   = 0;
      const int  error = posix_spawn(
        &pid, program.c_str(), &actions, nullptr, argv.data(), environ);
      posix_spawn_file_actions_destroy(&actions);
      if (error != 0)
        throw InputError("", "--study", "cannot start " + program);
      int           status = 0;
      struct rusage usage;
      wait4(pid, &status, 0, &usage);
      run.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
      run.memory_mb = usage.ru_maxrss / 1024.;
      run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 3;
    }

    /// The error columns the runs report (exact errors first).
    std::vector<std::string>
    error_keys(const std::vector<StudyRun> &runs)
    {
      std::vector<std::string> keys;
      for (const std::string key : {"rest_l2_error_relative",
                                    "rest_h1_error_relative",
                                    "l2_error_relative",
                                    "h1_error_relative",
                                    "mean_error_mm",
                                    "max_error_mm"})
        for (const StudyRun &run : runs)
          if (run.number(key))
            {
              keys.push_back(key);
              break;
            }
      return keys;
    }

    /// Relative difference of the largest displacement from the run with
    /// the most DoFs (the reference where no exact error is known).
    std::vector<std::optional<double>>
    difference_to_finest(const std::vector<StudyRun> &runs)
    {
      const StudyRun *finest = nullptr;
      for (const StudyRun &run : runs)
        if (run.number("max_displacement_mm") &&
            (!finest || run.number("n_dofs").value_or(0) >
                          finest->number("n_dofs").value_or(0)))
          finest = &run;
      std::vector<std::optional<double>> result;
      for (const StudyRun &run : runs)
        if (finest && &run != finest && run.number("max_displacement_mm"))
          result.push_back(
            std::abs(*run.number("max_displacement_mm") -
                     *finest->number("max_displacement_mm")) /
            std::max(std::abs(*finest->number("max_displacement_mm")), 1e-300));
        else
          result.push_back(std::nullopt);
      return result;
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
        args.insert(args.end(), {"--set", "Output/Directory=" + out, prm_file});
        std::cout << "study run " << i + 1 << "/" << all.size() << ": "
                  << described << " ... " << std::flush;
        spawn(program, args, out + "/screen.log", run);
        try
          {
            boost::property_tree::read_json(out + "/summary.json", run.summary);
          }
        catch (const std::exception &)
          {
            // A run that stopped before its summary: its exit code says so.
          }
        std::cout << (run.exit_code == 0 ?
                        "done" :
                        "FAILED (exit code " + std::to_string(run.exit_code) +
                          ", see " + out + "/screen.log)")
                  << ", " << long(run.number("n_dofs").value_or(0)) << " DoFs, "
                  << std::setprecision(3) << run.seconds << " s, "
                  << run.memory_mb << " MB" << std::endl;
        worst = std::max(worst, run.exit_code);
        runs.push_back(run);
      }
    write_study_tables(axes, runs, directory);
    std::cout << "study: " << runs.size() << " runs; " << directory
              << "/study.csv, study.txt, study_error_vs_time.svg" << std::endl;
    return worst;
  }

  void
  write_study_tables(const std::vector<StudyAxis> &axes,
                     const std::vector<StudyRun>  &runs,
                     const std::string            &directory)
  {
    const std::vector<std::string>        errors = error_keys(runs);
    const auto                            finest = difference_to_finest(runs);
    TableHandler                          table;
    std::vector<std::string>              header = {"run"};
    std::vector<std::vector<std::string>> rows;
    for (const StudyAxis &axis : axes)
      header.push_back(axis.parameter.substr(axis.parameter.rfind('/') + 1));
    for (const std::string key :
         {"converged", "n_dofs", "newton_iterations", "inverse_iterations"})
      header.push_back(key);
    header.insert(header.end(), errors.begin(), errors.end());
    header.insert(header.end(),
                  {"max_displacement_mm",
                   "max_displacement_difference_to_finest",
                   "wall_seconds",
                   "peak_memory_MB"});
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
        row.push_back(run.summary.get<std::string>("converged", "false"));
        for (const std::string key :
             {"n_dofs", "newton_iterations", "inverse_iterations"})
          row.push_back(text(run.number(key)));
        for (const std::string &key : errors)
          row.push_back(text(run.number(key)));
        row.push_back(text(run.number("max_displacement_mm")));
        row.push_back(text(finest[r]));
        row.push_back(text(run.seconds));
        row.push_back(text(run.memory_mb));
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
              out << (c ? "," : "") << row[c];
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
    // Plot the first exact error, else the difference to the finest run.
    std::vector<std::optional<double>> plotted = finest;
    std::string name = "max displacement difference to the finest run";
    if (!errors.empty())
      {
        name = errors[0];
        for (unsigned int r = 0; r < runs.size(); ++r)
          plotted[r] = runs[r].number(errors[0]);
      }
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
