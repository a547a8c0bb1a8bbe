// The scan options dialog: which IDs and which baud rates to look at.
#pragma once

#include "feetechsession.h"

#include <QDialog>
#include <QVector>

class QCheckBox;
class QLabel;
class QPushButton;
class QSpinBox;

class ScanDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ScanDialog(const feetech::ScanOptions &initial, QWidget *parent = nullptr);

    feetech::ScanOptions options() const;

private:
    void updateEstimate();

    QSpinBox *m_firstId = nullptr;
    QSpinBox *m_lastId = nullptr;
    QVector<QCheckBox *> m_bauds;
    QCheckBox *m_probe = nullptr;
    QLabel *m_estimate = nullptr;
    QPushButton *m_scan = nullptr;
};
