#include "wizard/point_labels.h"

#include <QRegularExpression>
#include <algorithm>
#include <vector>

namespace auv::ui {

QString withPointLabels(QString text, const VehicleProfile& vehicle) {
  std::vector<const AdjustmentPoint*> pts;
  for (const auto& p : vehicle.points)
    if (!p.label.empty()) pts.push_back(&p);
  std::sort(pts.begin(), pts.end(), [](auto* a, auto* b) { return a->name.size() > b->name.size(); });
  for (const auto* p : pts) {
    const QRegularExpression id("\\b" + QRegularExpression::escape(QString::fromStdString(p->name)) + "\\b");
    text.replace(id, QString::fromStdString(p->label));
  }
  return text;
}

}  // namespace auv::ui
