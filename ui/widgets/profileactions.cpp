// Profile actions: file dialogs, save with a completeness check, load through the diff dialog.
#include "profileactions.h"

#include "profile.h"
#include "profilediffdialog.h"
#include "recentfiles.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>

namespace {

struct ProfileActionsTr
{
    Q_DECLARE_TR_FUNCTIONS(ProfileActions)
};

} // namespace

namespace profileactions {

namespace { } // namespace

QString chooseSavePath(QWidget *parent, const QString &suggestedName)
{
    const QString path = QFileDialog::getSaveFileName(
        parent, ProfileActionsTr::tr("Save profile"),
        recentfiles::directory(recentfiles::Kind::Profile) + u'/' + suggestedName,
        ProfileActionsTr::tr("ServoBench profiles (*.json)"));
    recentfiles::add(recentfiles::Kind::Profile, path);
    return path;
}

QString chooseLoadPath(QWidget *parent)
{
    const QString path =
        QFileDialog::getOpenFileName(parent, ProfileActionsTr::tr("Load profile"),
                                     recentfiles::directory(recentfiles::Kind::Profile),
                                     ProfileActionsTr::tr("ServoBench profiles (*.json)"));
    recentfiles::add(recentfiles::Kind::Profile, path);
    return path;
}

bool save(const QString &path, const model::ParameterModel &parameters, const QString &family,
          const QString &modelName, const QVector<model::Definition> &definitions, bool withEdits,
          util::FileError *error)
{
    const profile::Profile saved = profile::fromModel(parameters, family, modelName, withEdits);
    for (const model::Definition &definition : definitions) {
        if (!saved.value(definition.key)) {
            util::report(
                error,
                util::FileError(util::FileError::Code::NothingToSave,
                                ProfileActionsTr::tr("Read the servo before saving a profile: "
                                                     "not every value is known."))
                    .withField(definition.key));
            return false;
        }
    }
    return profile::save(path, saved, definitions, error);
}

LoadOutcome loadAsEdits(QWidget *parent, const QString &path, const QString &family,
                        const QVector<model::Definition> &definitions,
                        model::ParameterModel &parameters, QString *error)
{
    util::FileError why;
    const auto loaded = profile::load(path, family, definitions, &why);
    if (!loaded) {
        if (error)
            *error = ProfileActionsTr::tr("The profile was not loaded: %1").arg(why.describe());
        return LoadOutcome::Failed;
    }
    const QVector<profile::DiffRow> rows = profile::diff(*loaded, parameters);
    if (rows.isEmpty())
        return LoadOutcome::AlreadyEqual;
    ProfileDiffDialog dialog(QDir::toNativeSeparators(path), rows, parameters, parent);
    if (dialog.exec() != QDialog::Accepted)
        return LoadOutcome::Cancelled;
    for (const profile::DiffRow &row : rows)
        parameters.edit(row.key, row.file);
    return LoadOutcome::Loaded;
}

QString outcomeMessage(LoadOutcome outcome)
{
    switch (outcome) {
    case LoadOutcome::AlreadyEqual:
        return ProfileActionsTr::tr("The servo already holds every value of this profile");
    case LoadOutcome::Loaded:
        return ProfileActionsTr::tr("Profile loaded as edits: review them, then Apply");
    case LoadOutcome::Failed:
    case LoadOutcome::Cancelled:
        break;
    }
    return {};
}

} // namespace profileactions
