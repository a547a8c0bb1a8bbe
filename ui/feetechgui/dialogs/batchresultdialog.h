// The outcome of programming several servos: one row per servo with its status, the registers
// written and what went wrong.
#pragma once

#include "settingsfile.h"

#include <QDialog>

class QTableWidget;

class BatchResultDialog : public QDialog
{
    Q_OBJECT

public:
    enum Column { ServoColumn, StatusColumn, ChangedColumn, ErrorColumn, ColumnCount };

    BatchResultDialog(const QString &source, const QVector<feetech::ProgramOutcome> &outcomes,
                      QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }

private:
    QTableWidget *m_table = nullptr;
};
