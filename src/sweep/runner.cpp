#include "sweep/runner.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>

#include "numerics/error.hpp"

namespace tribolab::sweep {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

bool valid_name(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_';
    if (!ok) return false;
  }
  return true;
}

/// Starts `n` threads running `work`. When the system refuses one (std::system_error: a
/// thread or address-space limit), `abandon(started)` must make the started ones return;
/// they are joined and an InputError says how many could be started.
template <class Work, class Abandon>
std::vector<std::thread> start_threads(int n, const Work& work, const Abandon& abandon) {
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(n));
  try {
    for (int i = 0; i < n; ++i) pool.emplace_back(work);
  } catch (const std::system_error& e) {
    const int started = static_cast<int>(pool.size());
    abandon(started);
    for (std::thread& t : pool) t.join();
    throw InputError(field("threads") + ": the system refused to start thread " + std::to_string(started + 1) +
                     " of " + std::to_string(n) + " (" + e.what() + "); ask for fewer");
  }
  return pool;
}

}  // namespace

std::string threads_error(int threads) {
  if (threads >= 0 && threads <= kMaxThreads) return {};
  return "threads must be 0 (all cores) to " + std::to_string(kMaxThreads) + ", got " + std::to_string(threads);
}

std::string CellModel::validate() const {
  if (output_names.empty() || output_names.size() > kMaxOutputs) {
    return "a cell model needs 1 to " + std::to_string(kMaxOutputs) + " outputs, got " +
           std::to_string(output_names.size());
  }
  for (std::size_t i = 0; i < output_names.size(); ++i) {
    if (!valid_name(output_names[i])) {
      return "output name '" + output_names[i] + "' must be letters, digits and '_'";
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (output_names[i] == output_names[j]) return "output '" + output_names[i] + "' given twice";
    }
    if (quantity_from_name(output_names[i]) || output_names[i] == "cell") {
      return "output name '" + output_names[i] + "' is the name of an input column";
    }
  }
  if (!evaluate) return "the cell model has no evaluate function";
  if (description.find_first_of("\r\n") != std::string::npos) {
    return "the model description must be one line";
  }
  return {};
}

int CellModel::output_index(const std::string& name) const {
  for (std::size_t i = 0; i < output_names.size(); ++i) {
    if (output_names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::string RunOptions::validate() const {
  if (auto e = threads_error(threads); !e.empty()) return e;
  if (chunk_cells < 0) return "chunk_cells must be >= 0 (0 = automatic)";
  if (!(progress_interval_s > 0)) return "progress_interval_s must be > 0";
  return {};
}

int resolve_threads(int threads) {
  if (threads > 0) return threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

RunSummary run_cells(const GridSpec& grid, const CellModel& model, const Shard& shard,
                     std::int64_t first_local, const RunOptions& options, const ResultSink& sink,
                     std::int64_t end_local) {
  TRIBOLAB_ASSERT(grid.validate().empty(), grid.validate());
  TRIBOLAB_ASSERT(model.validate().empty(), model.validate());
  TRIBOLAB_ASSERT(shard.validate().empty(), shard.validate());
  TRIBOLAB_ASSERT(options.validate().empty(), options.validate());
  const std::int64_t n_local = shard.cells(grid.cell_count());
  const std::int64_t end = end_local < 0 ? n_local : end_local;
  TRIBOLAB_ASSERT(first_local >= 0 && first_local <= end && end <= n_local,
                  "cells [" + std::to_string(first_local) + ", " + std::to_string(end) + ") of " +
                      std::to_string(n_local));

  const Clock::time_point t0 = Clock::now();
  RunSummary summary;
  const int n_threads = resolve_threads(options.threads);
  summary.threads = n_threads;
  const std::int64_t cells = end - first_local;
  const std::size_t n_out = model.output_names.size();
  const std::int64_t chunk =
      options.chunk_cells > 0
          ? options.chunk_cells
          : std::clamp<std::int64_t>(cells / (std::int64_t{n_threads} * 32), 1, 1024);
  const std::int64_t n_chunks = (cells + chunk - 1) / chunk;

  // A window of W chunk slots: chunk c lives in slot c % W and may be computed only once
  // chunk c - W has been committed. Workers may thus run at most W chunks ahead of the
  // writer, memory stays bounded, and commits happen in order.
  struct Slot {
    std::vector<CellInput> inputs;
    std::vector<double> outputs;
    std::string text;
    std::int64_t chunk = -1;
    bool ready = false;
  };
  const std::int64_t window = std::int64_t{n_threads} * 4;
  std::vector<Slot> slots(static_cast<std::size_t>(std::min(window, std::max<std::int64_t>(n_chunks, 1))));
  for (Slot& s : slots) {
    s.inputs.resize(static_cast<std::size_t>(chunk));
    s.outputs.resize(static_cast<std::size_t>(chunk) * n_out);
  }
  const auto n_slots = static_cast<std::int64_t>(slots.size());

  std::mutex mutex;
  std::condition_variable cv_window, cv_ready;
  std::atomic<std::int64_t> next_chunk{0};
  std::int64_t committed = 0;  // chunks committed; guarded by mutex
  int workers_running = n_threads;
  bool stop = false;
  std::exception_ptr error;
  auto cancelled = [&] { return options.cancel != nullptr && options.cancel->load(); };

  auto worker = [&] {
    try {
      while (true) {
        const std::int64_t c = next_chunk.fetch_add(1);
        if (c >= n_chunks) break;
        {
          std::unique_lock lock(mutex);
          while (!(c < committed + n_slots || stop)) {
            cv_window.wait_for(lock, std::chrono::milliseconds(50));
            if (cancelled()) stop = true;
          }
          if (stop || cancelled()) {
            stop = true;
            break;
          }
        }
        Slot& slot = slots[static_cast<std::size_t>(c % n_slots)];
        const std::int64_t first = first_local + c * chunk;
        const std::int64_t count = std::min(chunk, end - first);
        for (std::int64_t k = 0; k < count; ++k) {
          const CellInput in = grid.cell(shard.global(first + k));
          slot.inputs[static_cast<std::size_t>(k)] = in;
          const CellOutputs out = model.evaluate(in);
          std::copy_n(out.begin(), n_out, slot.outputs.begin() + static_cast<std::ptrdiff_t>(k * static_cast<std::int64_t>(n_out)));
        }
        if (sink.encode) {
          slot.text.clear();
          sink.encode(ChunkView{first, count, slot.inputs.data(), slot.outputs.data(), n_out},
                      slot.text);
        }
        {
          std::lock_guard lock(mutex);
          slot.chunk = c;
          slot.ready = true;
        }
        cv_ready.notify_all();
      }
    } catch (...) {
      std::lock_guard lock(mutex);
      if (!error) error = std::current_exception();
      stop = true;
    }
    {
      std::lock_guard lock(mutex);
      --workers_running;
    }
    cv_ready.notify_all();
    cv_window.notify_all();
  };

  std::vector<std::thread> pool = start_threads(n_threads, worker, [&](int started) {
    {
      std::lock_guard lock(mutex);
      stop = true;
      workers_running -= n_threads - started;  // the never started never decrement it
    }
    cv_window.notify_all();
  });

  auto report = [&](std::int64_t done_chunks) {
    if (!options.progress) return;
    Progress p;
    p.done = std::min(end, first_local + done_chunks * chunk);
    p.total = n_local;
    p.elapsed_s = seconds_since(t0);
    p.rate = p.elapsed_s > 0 ? static_cast<double>(p.done - first_local) / p.elapsed_s : 0;
    options.progress(p);
  };

  // The writer: commits chunk c once it is ready, in order, until all are committed or
  // every worker has stopped (cancellation or error) and the next chunk will never come.
  std::exception_ptr commit_error;
  Clock::time_point last_report = Clock::now();
  std::int64_t c = 0;
  while (c < n_chunks) {
    Slot& slot = slots[static_cast<std::size_t>(c % n_slots)];
    bool have = false;
    {
      std::unique_lock lock(mutex);
      cv_ready.wait_for(lock, std::chrono::duration<double>(options.progress_interval_s), [&] {
        return (slot.ready && slot.chunk == c) || workers_running == 0;
      });
      have = slot.ready && slot.chunk == c;
      if (!have && workers_running == 0) break;
    }
    if (have) {
      if (sink.commit) {
        const std::int64_t first = first_local + c * chunk;
        const std::int64_t count = std::min(chunk, end - first);
        try {
          sink.commit(ChunkView{first, count, slot.inputs.data(), slot.outputs.data(), n_out},
                      slot.text);
        } catch (...) {
          commit_error = std::current_exception();
        }
      }
      {
        std::lock_guard lock(mutex);
        slot.ready = false;
        if (commit_error) {
          stop = true;
        } else {
          committed = ++c;
        }
      }
      cv_window.notify_all();
      if (commit_error) break;
    }
    if (seconds_since(last_report) >= options.progress_interval_s) {
      report(c);
      last_report = Clock::now();
    }
  }
  {
    std::lock_guard lock(mutex);
    stop = true;
  }
  cv_window.notify_all();
  for (std::thread& t : pool) t.join();
  if (commit_error) std::rethrow_exception(commit_error);
  if (error) std::rethrow_exception(error);
  report(c);
  summary.cells_computed = std::min(cells, c * chunk);
  summary.status = c == n_chunks ? RunSummary::Status::completed : RunSummary::Status::cancelled;
  summary.seconds = seconds_since(t0);
  return summary;
}

std::vector<double> evaluate_grid(const GridSpec& grid, const CellModel& model,
                                  const RunOptions& options) {
  const std::size_t n_out = model.output_names.size();
  std::vector<double> values(static_cast<std::size_t>(grid.cell_count()) * n_out);
  ResultSink sink;
  sink.commit = [&](const ChunkView& v, const std::string&) {
    std::copy_n(v.outputs, static_cast<std::size_t>(v.count) * n_out,
                values.begin() + static_cast<std::ptrdiff_t>(v.first_local * static_cast<std::int64_t>(n_out)));
  };
  RunOptions opts = options;
  opts.cancel = nullptr;
  run_cells(grid, model, Shard{}, 0, opts, sink);
  return values;
}

void parallel_for(std::int64_t n, int threads, const std::function<void(std::int64_t)>& f) {
  const int n_threads = static_cast<int>(std::min<std::int64_t>(resolve_threads(threads), std::max<std::int64_t>(n, 1)));
  std::atomic<std::int64_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  auto work = [&] {
    while (!failed.load()) {
      const std::int64_t i = next.fetch_add(1);
      if (i >= n) return;
      try {
        f(i);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        failed = true;
      }
    }
  };
  std::vector<std::thread> pool = start_threads(n_threads - 1, work, [&](int) { failed = true; });
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace tribolab::sweep
