// The map runner: a pool of threads taking curves in turn; the fits are reported in input order.
#include "engine/fit/fit_map.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace mdrsim::fit {

std::vector<CurveRef> every_curve(const std::vector<measured::MeasuredFile>& files) {
  std::vector<CurveRef> curves;
  for (std::size_t f = 0; f < files.size(); ++f) {
    for (std::size_t c = 0; c < files[f].curves.size(); ++c) curves.push_back({f, c});
  }
  return curves;
}

std::vector<CurveFit> fit_curves(const std::vector<measured::MeasuredFile>& files,
                                 const std::vector<CurveRef>& curves, measured::SegmentKind segment,
                                 const CurveFitOptions& options, const MapRun& run) {
  std::vector<std::optional<CurveFit>> done(curves.size());
  std::mutex mutex;  // guards everything below that the workers share
  std::size_t next = 0;
  std::size_t reported = 0;
  bool stop = false;
  std::size_t failed_at = curves.size();
  std::exception_ptr failure;
  const auto fail = [&](std::size_t position, std::exception_ptr error) {
    if (position < failed_at) {
      failed_at = position;
      failure = std::move(error);
    }
    stop = true;
  };
  const auto worker = [&] {
    while (true) {
      std::size_t position = 0;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        if (stop || next >= curves.size()) return;
        position = next++;
      }
      std::optional<CurveFit> fit;
      std::exception_ptr error;
      try {
        const CurveRef& ref = curves[position];
        fit = fit_curve(files.at(ref.file), ref.curve, segment, options);
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      if (error) {
        fail(position, error);
        continue;
      }
      done[position] = std::move(fit);
      try {
        while (reported < curves.size() && done[reported] && !stop) {
          if (run.on_fit) run.on_fit(reported, *done[reported]);
          ++reported;
          if (run.on_progress) run.on_progress(reported);
        }
      } catch (...) {
        fail(reported, std::current_exception());
      }
    }
  };
  const int threads = static_cast<int>(std::max<std::size_t>(
      1, std::min<std::size_t>(static_cast<std::size_t>(std::max(1, run.threads)), curves.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  std::vector<CurveFit> fits;
  fits.reserve(curves.size());
  for (std::optional<CurveFit>& fit : done) fits.push_back(std::move(*fit));
  return fits;
}

}  // namespace mdrsim::fit
