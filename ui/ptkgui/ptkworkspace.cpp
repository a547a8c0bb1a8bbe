// The PTK workspace: Read and Apply through ptk::Client, the page's busy state while it writes,
// and profiles saved from and loaded into the form.
#include "ptkworkspace.h"

#include "parametermodel.h"
#include "parameterpage.h"
#include "profileactions.h"
#include "ptkclient.h"

#include <QDir>
#include <QVBoxLayout>

namespace {
const QString kPtkFamily = QStringLiteral("ptk");
} // namespace

PtkWorkspace::PtkWorkspace(ptk::Client *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("ptkWorkspace"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    ParameterPage::Options options;
    options.objectName = QStringLiteral("ptkPage");
    m_page = new ParameterPage(m_client->model(), options, this);
    layout->addWidget(m_page);

    connect(m_client, &ptk::Client::statusChanged, this,
            [this](const seriallink::ConnectionStatus &status) {
                m_page->setLinkReady(status.state == seriallink::ConnectionState::Connected);
                // A link that went away ends an Apply without its finished signal.
                if (!m_client->isBusy() && m_page->isBusy())
                    m_page->setBusy(false);
            });
    connect(m_client, &ptk::Client::applyProgress, m_page, &ParameterPage::setProgress);
    connect(m_client, &ptk::Client::applyFinished, this, &PtkWorkspace::onApplyFinished);
    connect(m_client, &ptk::Client::readFinished, this, [this](bool ok, const QString &why) {
        if (ok)
            emit message(tr("Read all parameters"));
        else
            emit problem(tr("Read failed: %1").arg(why));
    });
    connect(m_page, &ParameterPage::readRequested, this, [this] {
        emit actionStarted();
        m_client->readAll();
    });
    connect(m_page, &ParameterPage::applyRequested, this, &PtkWorkspace::apply);
    connect(m_page, &ParameterPage::saveProfileRequested, this, &PtkWorkspace::chooseProfileToSave);
    connect(m_page, &ParameterPage::loadProfileRequested, this, &PtkWorkspace::chooseProfileToLoad);
}

void PtkWorkspace::apply()
{
    emit actionStarted();
    QString error;
    if (!m_client->apply(&error)) {
        emit problem(tr("Nothing was written: %1").arg(error));
        return;
    }
    m_page->setBusy(true, tr("Writing N1…N12, then reading back…"));
}

void PtkWorkspace::onApplyFinished(bool ok, const QString &message)
{
    m_page->setBusy(false);
    bool mismatch = false;
    for (const model::Definition &definition : m_client->model()->definitions())
        mismatch = mismatch || m_client->model()->state(definition.key) == model::State::Mismatch;
    if (!ok)
        emit problem(message);
    else if (mismatch)
        emit problem(tr("The servo did not take every value: the fields marked Mismatch hold "
                        "something else than was written."));
    else
        emit this->message(tr("Written and verified"));
}

void PtkWorkspace::chooseProfileToSave()
{
    const QString path = profileactions::chooseSavePath(this, QStringLiteral("ptk-servo.json"));
    if (!path.isEmpty())
        saveProfile(path);
}

bool PtkWorkspace::saveProfile(const QString &path)
{
    // What the form shows: the servo's values with any edits not yet applied.
    util::FileError error;
    if (!profileactions::save(path, *m_client->model(), kPtkFamily, {},
                              m_client->model()->definitions(), true, &error)) {
        emit problem(error.describe());
        return false;
    }
    emit message(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

void PtkWorkspace::chooseProfileToLoad()
{
    const QString path = profileactions::chooseLoadPath(this);
    if (!path.isEmpty())
        loadProfile(path);
}

void PtkWorkspace::loadProfile(const QString &path)
{
    if (m_client->isBusy()) {
        emit problem(tr("Wait for the running read or Apply to finish before loading a profile."));
        return;
    }
    QString error;
    const profileactions::LoadOutcome outcome = profileactions::loadAsEdits(
        this, path, kPtkFamily, m_client->model()->definitions(), *m_client->model(), &error);
    if (outcome == profileactions::LoadOutcome::Failed)
        emit problem(error);
    else if (const QString note = profileactions::outcomeMessage(outcome); !note.isEmpty())
        emit message(note);
}
