// Runs the hard contact cases (src/bench/hard_contact.hpp) and prints each figure against the
// bound issue "Contact III" sets: `contact_hard` for all of them, `contact_hard NAME...` for some.
// Exits 0 whether or not they hold: it measures, the tests judge.
#include <cstdio>
#include <string>
#include <vector>

#include "bench/hard_contact.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> names(argv + 1, argv + argc);
  if (names.empty()) names = tumble::bench::hard_contact_case_names();
  int held = 0, figures = 0;
  std::printf("%-15s %-52s %12s %9s  %s\n", "case", "measure", "value", "bound", "holds");
  for (const std::string& name : names) {
    const tumble::bench::HardContactCase result = tumble::bench::run_hard_contact_case(name);
    if (result.figures.empty()) {
      std::fprintf(stderr, "contact_hard: no case named \"%s\"\n", name.c_str());
      return 2;
    }
    for (const tumble::bench::HardContactFigure& figure : result.figures) {
      std::printf("%-15s %-52s %12.3e %9.0e  %s\n", result.name.c_str(), figure.measure.c_str(),
                  figure.value, figure.bound, figure.holds() ? "yes" : "NO");
      held += figure.holds();
      ++figures;
    }
    std::fflush(stdout);
  }
  std::printf("%d of %d figures hold\n", held, figures);
  return 0;
}
