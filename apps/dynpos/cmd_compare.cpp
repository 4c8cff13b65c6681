// dynpos compare A.json B.json (placeholder until implemented).

#include "commands.hpp"

namespace dynpos::cli {

void register_compare(CLI::App& app) {
  add_planned(app, "compare", "Compare two results of the same analysis (A.json B.json)",
              "side-by-side tables with differences, e.g. before and after a retrofit");
}

}  // namespace dynpos::cli
