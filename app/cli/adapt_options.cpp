#include "app/cli/adapt_options.h"

namespace app {

std::optional<engine::AdaptiveSettings> adaptiveSettings(const AdaptOptions& options, const engine::Scene& scene) {
  if (options.off || (!scene.adaptive && !options.threshold && !options.minElementSize)) return std::nullopt;
  engine::AdaptiveSettings settings = scene.adaptive.value_or(engine::AdaptiveSettings{});
  if (options.threshold) settings.threshold = *options.threshold;
  if (options.minElementSize) settings.minElementSize = *options.minElementSize;
  return settings;
}

}  // namespace app
