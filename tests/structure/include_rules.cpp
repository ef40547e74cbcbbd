#include "tests/structure/include_rules.hpp"

#include <map>
#include <optional>
#include <set>

namespace lathesim::structure {
namespace {

std::string folderOf(const std::string& file) {
  const auto slash = file.rfind('/');
  return slash == std::string::npos ? "." : file.substr(0, slash);
}

std::string childPath(const FloorScope& scope, const std::string& child) {
  if (child == ".") return scope.folder == "." ? "the root" : scope.folder + "/ (its own files)";
  return scope.folder == "." ? child + "/" : scope.folder + "/" + child + "/";
}

std::string where(const Include& include) { return include.file + ":" + std::to_string(include.line); }

}  // namespace

std::string describe(const Violation& violation) {
  std::string text = violation.file;
  if (violation.line > 0) text += ":" + std::to_string(violation.line);
  if (!violation.target.empty()) text += ": #include \"" + violation.target + "\"";
  return text + ": " + violation.rule;
}

std::vector<Violation> floorViolations(const std::vector<Include>& includes, const FloorTable& table) {
  std::vector<Violation> violations;
  for (const Include& include : includes) {
    for (const FloorScope& scope : table.scopes) {
      const auto from = childOf(scope, include.file);
      const auto to = childOf(scope, include.target);
      if (!from || !to || *from == *to) continue;
      const auto fromFloor = scope.floorOf.find(*from);
      const auto toFloor = scope.floorOf.find(*to);
      if (fromFloor == scope.floorOf.end() || toFloor == scope.floorOf.end()) continue;  // unplacedFiles
      if (toFloor->second < fromFloor->second) continue;
      const std::string floors = " (floor " + std::to_string(fromFloor->second) + " includes floor " +
                                 std::to_string(toFloor->second) + " in floors.txt's [" + scope.folder + "])";
      const std::string rule = toFloor->second > fromFloor->second
          ? childPath(scope, *from) + " reaches up to " + childPath(scope, *to) + floors
          : childPath(scope, *from) + " includes its neighbour " + childPath(scope, *to) +
                " on the same floor" + floors;
      violations.push_back({include.file, include.line, include.target, rule});
    }
  }
  return violations;
}

std::vector<Violation> unplacedFiles(const std::vector<std::string>& files, const FloorTable& table) {
  std::vector<Violation> violations;
  for (const std::string& file : files) {
    for (const FloorScope& scope : table.scopes) {
      const auto child = childOf(scope, file);
      if (child && !scope.floorOf.count(*child)) {
        violations.push_back({file, 0, "", childPath(scope, *child) + " has no floor in floors.txt's [" +
                                               scope.folder + "]: place it"});
      }
    }
  }
  return violations;
}

std::vector<Violation> folderCycles(const std::vector<Include>& includes) {
  // folder → folder it includes → the first include that makes the step
  std::map<std::string, std::map<std::string, Include>> steps;
  for (const Include& include : includes) {
    const std::string from = folderOf(include.file);
    const std::string to = folderOf(include.target);
    if (from != to) steps[from].emplace(to, include);
  }
  // The path from `start` to `goal` by a breadth-first search, as the folders after `start`.
  auto pathBetween = [&](const std::string& start, const std::string& goal) -> std::optional<std::vector<std::string>> {
    std::map<std::string, std::string> cameFrom{{start, ""}};
    std::vector<std::string> frontier{start};
    while (!frontier.empty()) {
      std::vector<std::string> next;
      for (const std::string& folder : frontier) {
        const auto out = steps.find(folder);
        if (out == steps.end()) continue;
        for (const auto& [to, include] : out->second) {
          if (!cameFrom.emplace(to, folder).second) continue;
          if (to == goal) {
            std::vector<std::string> path{to};
            for (std::string at = folder; at != start; at = cameFrom[at]) path.insert(path.begin(), at);
            return path;
          }
          next.push_back(to);
        }
      }
      frontier = std::move(next);
    }
    return std::nullopt;
  };
  std::vector<Violation> violations;
  std::set<std::set<std::string>> reported;  // each cycle once, whichever folder it is found from
  for (const auto& [from, targets] : steps) {
    for (const auto& [to, include] : targets) {
      auto back = pathBetween(to, from);
      if (!back) continue;
      std::vector<std::string> cycle{from, to};
      cycle.insert(cycle.end(), back->begin(), back->end());  // ends at `from` again
      const std::set<std::string> members(cycle.begin(), cycle.end());
      if (!reported.insert(members).second) continue;
      std::string rule = "folders include each other in a cycle: " + from;
      for (std::size_t i = 1; i < cycle.size(); ++i) {
        rule += " -> " + cycle[i] + " (" + where(steps[cycle[i - 1]].at(cycle[i])) + ")";
      }
      violations.push_back({include.file, include.line, include.target, rule});
    }
  }
  return violations;
}

}  // namespace lathesim::structure
