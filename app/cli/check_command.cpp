#include "app/cli/check_command.h"

#include "engine/geometry/model_check.h"
#include "engine/io/atomic_file.h"
#include "engine/io/load_scene.h"

#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <iostream>

namespace app {

int runCheck(const CheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const engine::Scene scene = engine::loadSceneFaces(options.model, options.load);
  if (!options.json.empty()) engine::checkCanWrite(options.json);
  const std::vector<engine::Finding> findings = engine::checkModel(scene);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  std::array<size_t, engine::kFindingKinds> counts{};
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const engine::Finding& f : findings) {
    ++counts[static_cast<size_t>(f.kind)];
    const engine::Surface& s = scene.surfaces[f.surface];
    std::cout << scene.file << ": " << engine::describeLocation(scene, f) << ": "
              << engine::nameOf(engine::severityOf(f.kind)) << ": " << engine::nameOf(f.kind) << ": " << f.message
              << "; walkrad: " << engine::actionOf(f.kind) << "\n";
    nlohmann::ordered_json entry = {{"kind", engine::idOf(f.kind)},
                                    {"name", engine::nameOf(f.kind)},
                                    {"severity", engine::nameOf(engine::severityOf(f.kind))},
                                    {"object", scene.objects[s.object].name},
                                    {"face", s.face},
                                    {"path", s.jsonPath},
                                    {"point", {f.point.x, f.point.y, f.point.z}},
                                    {"message", f.message},
                                    {"action", engine::actionOf(f.kind)}};
    if (f.other >= 0) {
      const engine::Surface& o = scene.surfaces[static_cast<size_t>(f.other)];
      entry["other"] = {{"object", scene.objects[o.object].name}, {"face", o.face}, {"path", o.jsonPath}};
    }
    list.push_back(entry);
  }

  nlohmann::ordered_json summary = nlohmann::ordered_json::object();
  std::cout << scene.file << ": " << scene.surfaces.size() << " faces checked in " << ms << " ms: " << findings.size()
            << (findings.size() == 1 ? " finding" : " findings");
  const char* separator = " (";
  for (size_t k = 0; k < counts.size(); ++k) {
    const auto kind = static_cast<engine::FindingKind>(k);
    summary[engine::idOf(kind)] = counts[k];
    if (counts[k] == 0) continue;
    std::cout << separator << counts[k] << " " << engine::nameOf(kind);
    separator = ", ";
  }
  std::cout << (findings.empty() ? "" : ")") << "\n";

  if (!options.json.empty()) {
    const nlohmann::ordered_json report = {{"file", scene.file},
                                           {"faces", scene.surfaces.size()},
                                           {"check_ms", ms},
                                           {"counts", summary},
                                           {"findings", list}};
    engine::writeFileAtomically(options.json, report.dump(2) + "\n");
  }
  return 0;
}

}  // namespace app
