#pragma once
// The model check's names in a technician's words: physics terms and
// equation channels are ids in core ("hull_compressibility",
// "vertical_velocity"); the pages show these names, translated.
#include <QString>
#include <string>

#include "common/message.h"
#include "discrepancy/physics_terms.h"

namespace auv::ui {

QString termLabel(const std::string& id);  // unknown ids: '_' read as spaces
QString channelLabel(discrepancy::Channel c);
// A model-check sentence from core (English, no message id yet) with its ids
// in words: term and channel ids, "ballast_state", "core/sim", and number
// ranges written "a--b".
QString readableModelText(const std::string& core_text);
// A model-check message: by its id in the wizard's words and language
// (advice_text.*), else its English made readable as above.
QString readableModelMessage(const Message& m);
// "equation error", "simulation error", "term contribution" in words.
QString residualSourceLabel(const std::string& source);

}  // namespace auv::ui
