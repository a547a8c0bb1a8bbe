// The packet window's sequence files: saving and loading through packetsequence, the dialogs,
// and the folder remembered among the recent files.
#include "packetsequencefiles.h"

#include "recentfiles.h"

#include <QFileDialog>
#include <QWidget>

PacketSequenceFiles::PacketSequenceFiles(const QVector<PacketFrame> &history, QWidget *window)
    : QObject(window)
    , m_history(history)
    , m_window(window)
{ }

bool PacketSequenceFiles::save(const QString &path, util::FileError *error) const
{
    return packetsequence::save(path, m_history, error);
}

bool PacketSequenceFiles::load(const QString &path, util::FileError *error)
{
    const auto frames = packetsequence::load(path, error);
    if (!frames)
        return false;
    emit loaded(*frames);
    return true;
}

void PacketSequenceFiles::chooseSave()
{
    if (m_history.isEmpty()) {
        emit reported(tr("The history is empty: there is nothing to save."), true);
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
        m_window, tr("Save packet sequence"),
        recentfiles::directory(recentfiles::Kind::PacketSequence) + QStringLiteral("/packets.json"),
        tr("ServoBench packet sequences (*.json)"));
    if (path.isEmpty())
        return;
    util::FileError error;
    if (save(path, &error)) {
        recentfiles::add(recentfiles::Kind::PacketSequence, path);
        emit reported(tr("Saved %n frame(s).", nullptr, int(m_history.size())), false);
    } else {
        emit reported(error.describe(), true);
    }
}

void PacketSequenceFiles::chooseLoad()
{
    const QString path =
        QFileDialog::getOpenFileName(m_window, tr("Load packet sequence"),
                                     recentfiles::directory(recentfiles::Kind::PacketSequence),
                                     tr("ServoBench packet sequences (*.json)"));
    if (path.isEmpty())
        return;
    util::FileError error;
    if (load(path, &error)) {
        recentfiles::add(recentfiles::Kind::PacketSequence, path);
        emit reported(tr("Loaded into the history: select a frame and Resend, or Send all."),
                      false);
    } else {
        emit reported(error.describe(), true);
    }
}
