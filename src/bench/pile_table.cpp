#include "bench/pile_table.hpp"

#include <string>

namespace tumble::bench {
namespace {

// One line of the table: a label, and one engine's value as text.
struct Row {
  const char* label;
  std::string (*value)(const PileRun& run, double dt);
};

std::string fixed(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The largest box speed at t = 10 s (m/s), where the earlier Bullet figure was taken.
std::string speed_at_10_s(const PileRun& run, double dt) {
  const auto step = static_cast<std::size_t>(10.0 / dt + 0.5);  // steps done at t = 10 s
  return step >= 1 && step <= run.top_speed.size() ? fixed(run.top_speed[step - 1], 3) : "-";
}

const Row kRows[] = {
    {"mean ms/step (whole run)",
     [](const PileRun& r, double) { return fixed(mean_step_ms(r), 2); }},
    {"mean cpu ms/step", [](const PileRun& r, double) { return fixed(mean_step_cpu_ms(r), 2); }},
    {"median ms/step", [](const PileRun& r, double) { return fixed(median_step_ms(r), 2); }},
    {"median cpu ms/step",
     [](const PileRun& r, double) { return fixed(median_step_cpu_ms(r), 2); }},
    {"ms/step at peak contacts",
     [](const PileRun& r, double) { return fixed(ms_at_peak_contacts(r), 2); }},
    {"peak contacts",
     [](const PileRun& r, double) {
       return r.contacts.empty() ? std::string("-")
                                 : std::to_string(r.contacts[peak_contact_step(r)]);
     }},
    {"peak at t (s)",
     [](const PileRun& r, double dt) { return fixed(peak_contact_time(r, dt), 2); }},
    {"contacts at end",
     [](const PileRun& r, double) {
       return r.contacts.empty() ? std::string("-") : std::to_string(r.contacts.back());
     }},
    {"largest penetration, poses (m)",
     [](const PileRun& r, double) { return fixed(r.largest_penetration_m, 4); }},
    {"boxes out of the bin", [](const PileRun& r, double) { return std::to_string(r.escaped); }},
    {"largest speed at 10 s (m/s)", speed_at_10_s},
    {"largest speed at end (m/s)",
     [](const PileRun& r, double) { return fixed(r.largest_final_speed, 3); }},
};

}  // namespace

void print_pile_table(std::FILE* out, const std::vector<PileRun>& runs, double dt) {
  std::fprintf(out, "%-30s", "");
  for (const PileRun& run : runs) std::fprintf(out, "  %-20s", run.engine.c_str());
  std::fputc('\n', out);
  for (const Row& row : kRows) {
    std::fprintf(out, "%-30s", row.label);
    for (const PileRun& run : runs) std::fprintf(out, "  %-20s", row.value(run, dt).c_str());
    std::fputc('\n', out);
  }
  if (runs.size() == 2) {
    const StepTimeRatios ratios = step_time_ratios(runs[0], runs[1]);
    std::fprintf(out,
                 "tumble / bullet, mean ms/step: %.2f (cpu %.2f); median ms/step: %.2f (cpu "
                 "%.2f), at peak contacts: %.2f\n",
                 ratios.mean_ms, ratios.mean_cpu_ms, ratios.median_ms, ratios.median_cpu_ms,
                 ratios.ms_at_peak_contacts);
  }
}

}  // namespace tumble::bench
