// The packet log dock: every frame in and out, with pause, clear, export and an errors filter.
#pragma once

#include "linktypes.h"

#include <QDockWidget>

class QAction;
class QLabel;
class QTableView;

namespace seriallink {
class PacketLogModel;
}

class PacketLogProxy;
class ShareRecordingWindow;

class PacketLogDock : public QDockWidget
{
    Q_OBJECT

public:
    // Frames the log shows at the least, however short the window.
    static constexpr int kLeastRows = 3;

    explicit PacketLogDock(QWidget *parent = nullptr);

    // The dock owns its model; the main window feeds it from the link's packet log signal.
    seriallink::PacketLogModel *model() const { return m_model; }
    void append(const seriallink::PacketLogEntry &entry);

    QTableView *view() const { return m_view; }

    // Shows the shared-bus recording at `path` in a window of its own, read-only; nullptr and
    // *error (the file's fault, for the user) when it cannot be read.
    ShareRecordingWindow *openRecording(const QString &path, QString *error);

private:
    void exportLog();
    void chooseRecording();
    void showCounts(int total, int errors);
    void updateCounts();
    void setErrorsOnly(bool errorsOnly);
    void followNewRows(int minimum, int maximum);

    seriallink::PacketLogModel *m_model = nullptr;
    PacketLogProxy *m_proxy = nullptr;
    QTableView *m_view = nullptr;
    QAction *m_pause = nullptr;
    QAction *m_clear = nullptr;
    QAction *m_export = nullptr;
    QAction *m_errorsOnly = nullptr;
    QAction *m_openRecording = nullptr;
    QLabel *m_counts = nullptr;
    int m_shownTotal = 0;
    int m_shownErrors = 0;
    bool m_atBottom = true; // the view follows new rows only while scrolled to the end
};
