// The calibration wizard's last page: each joint's offset and limits, their writing, the file.
#pragma once

#include "armcalibration.h"

#include <QVector>
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

// The wizard decides what the buttons do and when they may be used.
class CalibrationResultsPage : public QWidget
{
    Q_OBJECT

public:
    explicit CalibrationResultsPage(QWidget *parent = nullptr);

    // One row per joint: what is to be written, or why it is refused.
    void showResults(const QVector<feetech::JointCalibration> &results);
    // How the write of `row` ended.
    void showWritten(int row, bool ok, const QString &message);
    // What the page says of the writes, one true thing at a time: the results shown by
    // showResults are not written yet, then written (`verified` of `total` joints read back as
    // written), or being written.
    void showWriting();
    void showWriteOutcome(int verified, int total);
    QLabel *summary() const { return m_summary; }

    QProgressBar *progress() const { return m_progress; }
    QPushButton *writeButton() const { return m_write; }
    QPushButton *saveButton() const { return m_save; }
    QPushButton *recordAgainButton() const { return m_again; }

private:
    QLabel *m_summary = nullptr;
    QTableWidget *m_table = nullptr;
    QProgressBar *m_progress = nullptr;
    QPushButton *m_write = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_again = nullptr;
};
