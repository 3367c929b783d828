#pragma once
// Core's advice (common/message.h) in the technician's words and language:
// each message id has a wizard sentence (no CLI flags, channel ids or JSON
// paths) translated through tr() in the "Advice" context; short word
// arguments ("operating", "lighter") go through the "AdviceWord" context.
// A message without an id, or with one this table does not know, is shown
// as core wrote it.
#include <QString>
#include <QStringList>
#include <vector>

#include "common/message.h"

namespace auv::ui {

QString adviceText(const Message& m);

// Every message id the wizard has a sentence for (translation checks).
QStringList adviceIds();
// The wizard's English sentence for `id` (before translation), empty if none.
QString adviceSource(const QString& id);

}  // namespace auv::ui
