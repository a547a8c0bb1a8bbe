// Saving a servo's settings to a profile file and loading one back as edits, for every page.
#pragma once

#include "fileerror.h"
#include "parametermodel.h"

#include <QString>
#include <QVector>

class QWidget;

namespace profileactions {

// File dialogs in the user's documents folder; empty when cancelled.
QString chooseSavePath(QWidget *parent, const QString &suggestedName);
QString chooseLoadPath(QWidget *parent);

// Saves what `parameters` holds for `definitions`: with `withEdits` the form as shown, edits
// included; without, only what the servo holds (a backup). Refuses while any of them has not
// been read (NothingToSave). False and *error on failure.
bool save(const QString &path, const model::ParameterModel &parameters, const QString &family,
          const QString &modelName, const QVector<model::Definition> &definitions, bool withEdits,
          util::FileError *error);

enum class LoadOutcome { Failed, AlreadyEqual, Cancelled, Loaded };
// Validates the whole file, shows what it would change, and on OK turns those rows into edits.
LoadOutcome loadAsEdits(QWidget *parent, const QString &path, const QString &family,
                        const QVector<model::Definition> &definitions,
                        model::ParameterModel &parameters, QString *error);
// The note for the status bar after a load that changed nothing or made edits; empty for a
// failure (its error says why) and a cancel.
QString outcomeMessage(LoadOutcome outcome);

} // namespace profileactions
