#include "cli/sweep_options.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "cli/option_number.hpp"

namespace cerebellum {

namespace {

std::uint64_t whole(const std::string& option, const std::string& text, double lower, double upper) {
  const double v = option_number(option, text, "a whole number");
  if (v != static_cast<double>(static_cast<std::uint64_t>(v)) || v < lower || v > upper)
    throw std::invalid_argument(option + ": '" + text + "' is not a whole number in [" +
                                std::to_string(static_cast<std::uint64_t>(lower)) + ", " +
                                std::to_string(static_cast<std::uint64_t>(upper)) + "]");
  return static_cast<std::uint64_t>(v);
}

}  // namespace

std::string sweep_usage() {
  return "usage: cerebellum sweep FILE [-j N] [--out DIR] [--yes] [--slurm [--partition P] [--time T] [--tasks N]]\n"
         "       cerebellum sweep FILE --cell K [--out DIR] [--record FILE.mp4]\n"
         "       cerebellum sweep --status DIR\n"
         "Runs every cell of the scenario file's grid (docs/sweeps.md), each a lockstep run of the\n"
         "simulated robot in its own worker process (no sockets), and writes DIR/results.csv (one row\n"
         "per run) and DIR/summary.md (the outcomes and, for each failed run, the command replaying it).\n"
         "A rerun with the same DIR continues: finished cells are kept, crashed ones run again.\n"
         "  -j N           worker processes at once (default: all cores)\n"
         "  --out DIR      the output folder (default: sweep-<FILE's name>)\n"
         "  --yes          run a grid of more than " +
         std::to_string(kSweepConfirmAboveCells) +
         " cells\n"
         "  --cell K       run cell K alone and print its row (into DIR too with --out)\n"
         "  --record F.mp4 with --cell: a video of the run (headless rendering and ffmpeg, as cerebellum sim)\n"
         "  --slice I/N    run only the cells K with K % N == I, without gathering (a Slurm task)\n"
         "  --slurm        submit the sweep to Slurm as a job array (sbatch) and wait for it; DIR must\n"
         "                 be on a folder every node sees\n"
         "  --partition P  --time T (sbatch's --time)  --tasks N (array tasks, default one per cell up to 100)\n"
         "  --sbatch PATH  the sbatch program (default: sbatch on PATH)\n"
         "  --no-wait      submit and return; gather later with --status DIR\n"
         "  --status DIR   the progress of a sweep's folder; gathers its results so far\n"
         "Exit status: 0 every run ended ok, 1 some run did not, 2 bad input, 3 some worker crashed\n"
         "or cells are missing.\n";
}

SweepOptions parse_sweep_options(const std::vector<std::string>& args) {
  SweepOptions o;
  const auto value = [&](std::size_t& i) -> const std::string& {
    if (i + 1 >= args.size()) throw std::invalid_argument(args[i] + " needs a value");
    return args[++i];
  };
  const auto slurm = [&]() -> SlurmOptions& {
    if (!o.slurm) o.slurm = SlurmOptions{};
    return *o.slurm;
  };
  bool slurm_detail = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      o.help = true;
    } else if (a == "-j" || a == "--jobs") {
      o.jobs = static_cast<int>(whole(a, value(i), 1, 4096));
    } else if (a == "--out") {
      o.out = value(i);
    } else if (a == "--yes") {
      o.yes = true;
    } else if (a == "--cell") {
      o.cell = whole(a, value(i), 0, 1e15);
    } else if (a == "--record") {
      o.record_path = value(i);
    } else if (a == "--slice") {
      const std::string text = value(i);
      const auto slash = text.find('/');
      if (slash == std::string::npos) throw std::invalid_argument("--slice: '" + text + "' is not I/N");
      const std::uint64_t count = whole("--slice", text.substr(slash + 1), 1, 1e6);
      const std::uint64_t index = whole("--slice", text.substr(0, slash), 0, static_cast<double>(count - 1));
      o.slice = std::make_pair(index, count);
    } else if (a == "--status") {
      o.status_dir = value(i);
    } else if (a == "--slurm") {
      slurm();
    } else if (a == "--partition") {
      slurm().partition = value(i);
      slurm_detail = true;
    } else if (a == "--time") {
      slurm().time_limit = value(i);
      slurm_detail = true;
    } else if (a == "--tasks") {
      slurm().tasks = static_cast<int>(whole(a, value(i), 1, 100000));
      slurm_detail = true;
    } else if (a == "--sbatch") {
      slurm().sbatch = value(i);
      slurm_detail = true;
    } else if (a == "--no-wait") {
      slurm().wait = false;
      slurm_detail = true;
    } else if (!a.empty() && a[0] == '-') {
      throw std::invalid_argument("unknown option '" + a + "' (cerebellum sweep --help)");
    } else if (o.file.empty()) {
      o.file = a;
    } else {
      throw std::invalid_argument("one scenario file only; got '" + o.file + "' and '" + a + "'");
    }
  }
  if (o.help) return o;
  if (slurm_detail && std::find(args.begin(), args.end(), "--slurm") == args.end())
    throw std::invalid_argument("--partition, --time, --tasks, --sbatch and --no-wait go with --slurm");
  if (!o.status_dir.empty()) {
    if (!o.file.empty() || o.slurm || o.cell) throw std::invalid_argument("--status DIR takes no scenario file");
    return o;
  }
  if (o.file.empty()) throw std::invalid_argument("give the scenario file (cerebellum sweep --help)");
  if (o.cell && (o.slurm || o.slice)) throw std::invalid_argument("--cell runs one cell here; not with --slurm or --slice");
  if (!o.record_path.empty() && !o.cell) throw std::invalid_argument("--record FILE.mp4 films one cell: give --cell K");
  if (o.slurm && o.slice) throw std::invalid_argument("--slice is what each Slurm task runs; not with --slurm");
  if (o.out.empty() && !o.cell) o.out = "sweep-" + std::filesystem::path(o.file).stem().string();
  return o;
}

}  // namespace cerebellum
