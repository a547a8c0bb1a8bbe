// The packet window's sequence files: the history saved and loaded, with their file dialogs.
#include "packetwindow.h"

#include "recentfiles.h"

#include <QFileDialog>
#include <QTableWidget>

bool PacketWindow::saveSequence(const QString &path, QString *error) const
{
    return packetsequence::save(path, m_frames, error);
}

bool PacketWindow::loadSequence(const QString &path, QString *error)
{
    const auto frames = packetsequence::load(path, error);
    if (!frames)
        return false;
    for (const PacketFrame &frame : *frames)
        addHistoryRow(frame, tr("loaded, not sent"));
    return true;
}

void PacketWindow::chooseSave()
{
    if (m_frames.isEmpty()) {
        showMessage(tr("The history is empty: there is nothing to save."), true);
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save packet sequence"),
        recentfiles::directory(recentfiles::Kind::PacketSequence) + QStringLiteral("/packets.json"),
        tr("ServoBench packet sequences (*.json)"));
    if (path.isEmpty())
        return;
    QString error;
    if (saveSequence(path, &error)) {
        recentfiles::add(recentfiles::Kind::PacketSequence, path);
        showMessage(tr("Saved %n frame(s).", nullptr, int(m_frames.size())), false);
    } else {
        showMessage(error, true);
    }
}

void PacketWindow::chooseLoad()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Load packet sequence"), recentfiles::directory(recentfiles::Kind::PacketSequence),
        tr("ServoBench packet sequences (*.json)"));
    if (path.isEmpty())
        return;
    QString error;
    if (loadSequence(path, &error)) {
        recentfiles::add(recentfiles::Kind::PacketSequence, path);
        showMessage(tr("Loaded into the history: select a frame and Resend, or Send all."), false);
    } else {
        showMessage(error, true);
    }
}
