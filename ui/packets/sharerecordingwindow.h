// A shared bus's recording, read back: every frame with its time, who sent it and its meaning.
#pragma once

#include "sharerecording.h"

#include <QDialog>

class QStandardItemModel;
class QTableView;

// Read-only, not modal: opened from the packet log (Open recording…) beside the live log.
class ShareRecordingWindow : public QDialog
{
    Q_OBJECT

public:
    enum Column { TimeColumn, FromColumn, BytesColumn, MeaningColumn, ErrorColumn, ColumnCount };

    ShareRecordingWindow(const QString &path, const QVector<share::RecordedFrame> &frames,
                         QWidget *parent = nullptr);

    QTableView *view() const { return m_view; }
    QStandardItemModel *model() const { return m_model; }

    static QString directionText(share::FrameDirection direction);

private:
    QStandardItemModel *m_model = nullptr;
    QTableView *m_view = nullptr;
};
