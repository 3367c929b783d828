#include "vehicle/nearest_key.h"

#include <algorithm>

namespace auv {

std::size_t keyDistance(std::string_view a, std::string_view b) {
  // Optimal string alignment distance; keys are short, so the full table is cheap.
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

std::string nearestKey(std::string_view key, const std::vector<std::string>& known) {
  if (key.size() > 200) return {};  // a hostile key; no hint is worth the time
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, key.size() / 3) + 1;
  for (const auto& k : known) {
    const std::size_t dist = keyDistance(key, k);
    if (dist < best_d) {
      best_d = dist;
      best = k;
    }
  }
  return best;
}

}  // namespace auv
