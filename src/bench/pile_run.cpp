#include "bench/pile_run.hpp"

#include <algorithm>
#include <utility>

namespace tumble::bench {

namespace {

double median(std::vector<double> sorted) {
  if (sorted.empty()) return 0.0;
  const std::size_t middle = sorted.size() / 2;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(middle),
                   sorted.end());
  if (sorted.size() % 2 == 1) return sorted[middle];
  const double below = *std::max_element(sorted.begin(), sorted.begin() + middle);
  return 0.5 * (below + sorted[middle]);  // an even count: the mean of the two middle values
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  double total = 0.0;
  for (const double value : values) total += value;
  return total / static_cast<double>(values.size());
}

}  // namespace

double mean_step_ms(const PileRun& run) {
  return mean(run.step_ms);
}

double mean_step_cpu_ms(const PileRun& run) {
  return mean(run.step_cpu_ms);
}

double median_step_ms(const PileRun& run) {
  return median(run.step_ms);
}

double median_step_cpu_ms(const PileRun& run) {
  return median(run.step_cpu_ms);
}

std::size_t peak_contact_step(const PileRun& run) {
  const auto peak = std::max_element(run.contacts.begin(), run.contacts.end());  // the first
  return peak == run.contacts.end() ? 0 : static_cast<std::size_t>(peak - run.contacts.begin());
}

double peak_contact_time(const PileRun& run, double dt) {
  return static_cast<double>(peak_contact_step(run) + 1) * dt;
}

double ms_at_peak_contacts(const PileRun& run) {
  if (run.step_ms.empty()) return 0.0;
  const int peak = run.contacts.at(peak_contact_step(run));
  std::vector<double> near_peak;
  for (std::size_t n = 0; n < run.step_ms.size(); ++n) {
    if (run.contacts.at(n) >= 0.95 * peak) near_peak.push_back(run.step_ms[n]);
  }
  return median(std::move(near_peak));
}

StepTimeRatios step_time_ratios(const PileRun& first, const PileRun& second) {
  return {.mean_ms = mean_step_ms(first) / mean_step_ms(second),
          .mean_cpu_ms = mean_step_cpu_ms(first) / mean_step_cpu_ms(second),
          .median_ms = median_step_ms(first) / median_step_ms(second),
          .median_cpu_ms = median_step_cpu_ms(first) / median_step_cpu_ms(second),
          .ms_at_peak_contacts = ms_at_peak_contacts(first) / ms_at_peak_contacts(second)};
}

}  // namespace tumble::bench
