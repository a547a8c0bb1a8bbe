// The packet window's sequence files: the history saved to a file and a file loaded into it,
// with the file dialogs that ask where and the recent folders they start in.
#pragma once

#include "packetsequence.h"

#include <QObject>
#include <QVector>

class QWidget;

class PacketSequenceFiles : public QObject
{
    Q_OBJECT

public:
    // Saves `history` (the window's, which outlives this); `window` is the dialogs' parent.
    PacketSequenceFiles(const QVector<PacketFrame> &history, QWidget *window);

    bool save(const QString &path, util::FileError *error = nullptr) const;
    // The frames go to `loaded`; false and *error (naming the file and the entry at fault) when
    // the file is not a sequence.
    bool load(const QString &path, util::FileError *error = nullptr);

    // Ask where, then save or load; what came of it goes to `reported`.
    void chooseSave();
    void chooseLoad();

signals:
    void loaded(const QVector<PacketFrame> &frames);
    void reported(const QString &text, bool problem);

private:
    const QVector<PacketFrame> &m_history;
    QWidget *m_window = nullptr;
};
