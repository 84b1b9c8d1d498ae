#include "analysis/series.hpp"

#include "numerics/error.hpp"
#include "sweep/runner.hpp"

#include <chrono>
#include <exception>
#include <mutex>

namespace tribolab::analysis {

std::string SeriesOptions::validate() const {
  if (auto e = sweep::threads_error(threads); !e.empty()) return e;
  return {};
}

std::string locate(const std::string& source, const std::string& message) {
  if (!source.empty() && message.rfind(source, 0) == 0) return message;
  return source.empty() ? message : source + ": " + message;
}

std::vector<std::optional<RunError>> run_each(std::size_t n, const std::function<void(std::size_t)>& job,
                                              const SeriesOptions& options) {
  TRIBOLAB_ASSERT(options.validate().empty(), options.validate());
  std::vector<std::optional<RunError>> errors(n);
  std::mutex mutex;  // guards `done`, `failed` and the progress callback
  std::size_t done = 0, failed = 0;
  const auto t0 = std::chrono::steady_clock::now();
  // sweep::parallel_for hands out indices to a pool of threads; each job writes only its own
  // slot of `errors` (and of the caller's results), so the order of completion is irrelevant.
  sweep::parallel_for(static_cast<std::int64_t>(n), options.threads, [&](std::int64_t k) {
    const auto i = static_cast<std::size_t>(k);
    try {
      job(i);
    } catch (const Error& e) {  // InputError or SolverError
      errors[i] = RunError{e.message(field), e.where()};  // its fields kept marked: each front end spells them
    } catch (const std::exception& e) {
      errors[i] = RunError{e.what(), {}};
    } catch (...) {
      errors[i] = RunError{"unknown error", {}};
    }
    std::lock_guard lock(mutex);
    ++done;
    if (errors[i]) ++failed;
    if (options.progress) {
      SeriesProgress p;
      p.done = done;
      p.failed = failed;
      p.total = n;
      p.last = i;
      p.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      options.progress(p);
    }
  });
  return errors;
}

}  // namespace tribolab::analysis
