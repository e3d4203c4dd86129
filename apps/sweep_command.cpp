// mdrsim sweep: one run per row of the grid of --vary values, in parallel; each row goes to
// the CSV as soon as it and every row before it are done, so that a killed sweep keeps them.
#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <sys/signalfd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "apps/commands.hpp"
#include "apps/csv_sink.hpp"
#include "apps/output_file.hpp"
#include "apps/scene_input.hpp"
#include "apps/write_error.hpp"
#include "engine/base/text.hpp"
#include "engine/output/sweep_csv.hpp"
#include "engine/output/sweep_rows.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/run_label.hpp"
#include "engine/sweep/sweep_design.hpp"
#include "engine/sweep/sweep_grid.hpp"
#include "engine/sweep/sweep_progress.hpp"
#include "engine/sweep/usage_error.hpp"
#include "engine/sweep/vary_spec.hpp"

namespace mdrsim::cli {
namespace {

/// SIGINT and SIGTERM, read by a thread of its own from a signalfd: `on_signal` runs there
/// (and ends the process). Blocked from construction to destruction in this thread and in
/// every thread started meanwhile, so that no other thread takes them (in the mdrsim
/// process the sweep's threads are the only ones).
class SignalWatch {
 public:
  explicit SignalWatch(std::function<void(int)> on_signal) {
    sigemptyset(&signals_);
    sigaddset(&signals_, SIGINT);
    sigaddset(&signals_, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals_, &previous_);
    signal_fd_ = signalfd(-1, &signals_, SFD_CLOEXEC);
    if (signal_fd_ < 0 || pipe2(wake_, O_CLOEXEC) != 0) {
      pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
      throw std::runtime_error("sweep: cannot watch for signals: " + system_reason(errno));
    }
    watcher_ = std::thread([this, on_signal = std::move(on_signal)] {
      pollfd fds[2] = {{signal_fd_, POLLIN, 0}, {wake_[0], POLLIN, 0}};
      while (true) {
        if (poll(fds, 2, -1) < 0 && errno != EINTR) return;
        // A signal that came before the end is still obeyed (the exit code says it came).
        signalfd_siginfo info{};
        if ((fds[0].revents & POLLIN) != 0 && read(signal_fd_, &info, sizeof info) == sizeof info) {
          on_signal(static_cast<int>(info.ssi_signo));
        }
        if (fds[1].revents != 0) return;
      }
    });
  }
  SignalWatch(const SignalWatch&) = delete;
  SignalWatch& operator=(const SignalWatch&) = delete;
  ~SignalWatch() {
    const char byte = 0;
    while (write(wake_[1], &byte, 1) < 0 && errno == EINTR) {
    }
    watcher_.join();
    close(signal_fd_);
    close(wake_[0]);
    close(wake_[1]);
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }

 private:
  sigset_t signals_{};
  sigset_t previous_{};
  int signal_fd_ = -1;
  int wake_[2] = {-1, -1};
  std::thread watcher_;
};

/// Where a --resume sweep starts: the shard's rows already in the CSV. Refuses a CSV of
/// another scene, grid or shard. `keep` is set to the bytes to keep (a torn line is cut).
std::uint64_t resume_from(const std::string& path, const SweepIdentity& identity,
                          const std::string& header, std::uint64_t shard_rows, std::uint64_t& keep,
                          bool& fresh) {
  fresh = false;
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) {
      throw UsageError(
          fmt::format("--resume: cannot read '{}' ({})", printable(path), system_reason(errno)));
    }
    fresh = true;  // nothing to resume: a job array may pass --resume on every try
    return 0;
  }
  if (!S_ISREG(st.st_mode)) {
    throw UsageError(fmt::format("--resume: '{}' is not a regular file", printable(path)));
  }
  const SweepFile file = read_sweep_file(path, "--resume");
  const std::string head = identity_line(identity) + header;
  const std::string name = printable(path);
  if (file.header.empty()) {
    // Killed before its first two lines were whole: start again if they were ours.
    if (head.compare(0, file.head.size(), file.head) == 0) {
      fresh = true;
      return 0;
    }
  }
  const auto found = parse_identity_line(file.first_line);
  if (!found) {
    throw UsageError(fmt::format(
        "--resume: '{}' is not a sweep CSV (its first line is not '# mdrsim sweep: ...')", name));
  }
  if (found->scene != identity.scene) {
    throw UsageError(fmt::format(
        "--resume: '{}' is a sweep of another scene (scene {:016x}; this one is {:016x})", name,
        found->scene, identity.scene));
  }
  if (found->grid != identity.grid || found->rows != identity.rows) {
    throw UsageError(fmt::format(
        "--resume: '{}' is a sweep of another grid (grid {:016x} of {} rows; this one is {:016x} "
        "of {} rows)",
        name, found->grid, found->rows, identity.grid, identity.rows));
  }
  if (found->shard != identity.shard) {
    throw UsageError(fmt::format("--resume: '{}' is shard {}/{}; this sweep is shard {}/{}", name,
                                 found->shard.index, found->shard.count, identity.shard.index,
                                 identity.shard.count));
  }
  if (file.header != header) {
    throw UsageError(fmt::format(
        "--resume: '{}' has other columns than this sweep (written by another mdrsim?)", name));
  }
  if (file.rows > shard_rows) {
    throw UsageError(fmt::format("--resume: '{}' has {} rows, more than the {} of this sweep", name,
                                 file.rows, shard_rows));
  }
  keep = file.complete_bytes;
  return file.rows;
}

/// A sweep without --resume or --force never replaces a file's rows: a sweep run again with
/// the --csv of an earlier, longer one would silently leave three rows where there were
/// thousands. A device, a fifo or an empty file (one made by mktemp) holds no rows to lose.
void refuse_existing_csv(const std::string& path) {
  if (path == "-") return;
  struct stat st {};
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_size == 0) return;
  throw UsageError(
      fmt::format("--csv: '{}' exists (--resume finishes the sweep in it, --force replaces it)",
                  printable(path)));
}

/// The keys in command-line order: each --vary, then the --link flags that followed it.
std::vector<VarySpec> vary_keys(const SweepOptions& options, bool drawn) {
  std::vector<VarySpec> keys;
  std::size_t linked = 0;
  const auto add_links = [&](std::size_t varies) {
    for (; linked < options.link.size(); ++linked) {
      const std::size_t after =
          linked < options.link_after.size() ? options.link_after[linked] : options.vary.size();
      if (after > varies) return;
      VarySpec spec = parse_vary(options.link[linked], drawn, "--link");
      spec.linked = true;
      keys.push_back(std::move(spec));
    }
  };
  add_links(0);
  for (std::size_t v = 0; v < options.vary.size(); ++v) {
    keys.push_back(parse_vary(options.vary[v], drawn));
    add_links(v + 1);
  }
  return keys;
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

int sweep_command(const SweepOptions& options) {
  // From here on SIGINT/SIGTERM end the sweep with whole rows only (on_signal below).
  std::mutex mutex;  // guards everything the workers share, and the CSV
  std::uint64_t written = 0;
  std::uint64_t shard_rows = 0;
  std::string csv_name;
  const SignalWatch signals([&](int signal) {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!csv_name.empty()) {
      spdlog::warn("sweep: stopped by {} with {} of {} rows in {}; --resume finishes it",
                   signal == SIGINT ? "SIGINT" : "SIGTERM", written, shard_rows, csv_name);
    }
    std::_Exit(128 + signal);
  });

  const SweepDesign design = parse_design(options.design, options.samples, options.seed);
  const SweepGrid grid(vary_keys(options, design.drawn()), options.where, design);
  const Shard shard = options.shard.empty() ? Shard{} : parse_shard(options.shard);
  require_distinct_outputs({{"--csv", options.csv}}, options.scene);
  if (options.resume && options.csv == "-") {
    throw UsageError("--resume: needs --csv PATH (a sweep on standard output cannot resume)");
  }
  if (options.resume && options.force) {
    throw UsageError("--force: replaces the CSV that --resume finishes; give one of them");
  }
  if (!options.resume && !options.force) refuse_existing_csv(options.csv);
  const SceneDocument base = load_scene_document(options.scene, options.sets);
  const Registries registries = Registries::builtin();
  const SweepColumns columns = check_values(base, grid, registries);

  const SweepIdentity identity{scene_hash(read_bytes(options.scene), options.sets), grid.hash(),
                               grid.rows(), shard};
  const std::string header = csv_header(grid, columns);
  shard_rows = shard.rows_of(grid.rows());
  CsvSink csv(options.csv);
  std::uint64_t done = 0;
  std::uint64_t keep = 0;
  bool fresh = true;
  if (options.resume) done = resume_from(options.csv, identity, header, shard_rows, keep, fresh);
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (fresh) {
      csv.open_fresh(identity_line(identity) + header);
    } else {
      csv.open_resumed(keep);
    }
    written = done;
    csv_name = options.csv == "-" ? std::string("standard output")
                                  : fmt::format("'{}'", printable(options.csv));
  }

  const auto started = std::chrono::steady_clock::now();
  SweepProgress progress(done, shard_rows, started);
  const int threads = static_cast<int>(
      std::max<std::uint64_t>(1, std::min<std::uint64_t>(options.threads, shard_rows - done)));
  // Rows wait here for the rows before them; workers keep at most `window` rows ahead.
  std::map<std::uint64_t, std::string> finished;
  const std::uint64_t window = 1024 + 64 * static_cast<std::uint64_t>(threads);
  std::uint64_t next = done;
  bool stop = false;
  std::uint64_t failed_at = shard_rows;
  std::exception_ptr failure;
  std::condition_variable room;
  const auto worker = [&] {
    std::optional<SceneDocument> document;
    while (true) {
      std::uint64_t position = 0;
      {
        std::unique_lock<std::mutex> lock(mutex);
        room.wait(lock, [&] { return stop || next >= shard_rows || next < written + window; });
        if (stop || next >= shard_rows) return;
        position = next++;
      }
      std::string line;
      std::exception_ptr error;
      try {
        if (!document) document.emplace(base);  // a copy re-parses: once per worker
        line = run_row(*document, grid, shard.row(position), registries, columns);
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      if (error) {
        // The first failing row in row order is the one reported, whatever the threads did.
        if (position < failed_at) {
          failed_at = position;
          failure = error;
        }
        stop = true;
        room.notify_all();
        continue;
      }
      finished.emplace(position, std::move(line));
      try {
        for (auto it = finished.begin(); it != finished.end() && it->first == written;
             it = finished.erase(it)) {
          csv.write_all(it->second);
          ++written;
        }
        if (const auto line = progress.line(written, std::chrono::steady_clock::now())) {
          spdlog::info("{}", *line);
        }
      } catch (...) {
        if (!failure) failure = std::current_exception();
        failed_at = 0;
        stop = true;
      }
      room.notify_all();
    }
  };
  std::vector<std::thread> pool;
  {
    // The runs' own lines (each warning, its route) go at debug; the CSV keeps each row's
    // warning count and one line counts them by kind.
    const QuietRuns quiet(*spdlog::default_logger_raw());
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (const auto summary = quiet.summary()) spdlog::warn("{}", *summary);
  }
  if (failure) std::rethrow_exception(failure);
  spdlog::info("sweep: {} rows on {} in {:.3g} s{}{}", shard_rows - done,
               counted(threads, "thread"),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(),
               done > 0 ? fmt::format(" ({} were in the CSV already)", done) : std::string(),
               grid.rows() < grid.candidates()
                   ? fmt::format("; {} of {} {} pass --where", grid.rows(), grid.candidates(),
                                 grid.design().drawn() ? "samples" : "grid rows")
                   : std::string());
  return 0;
}

}  // namespace mdrsim::cli
