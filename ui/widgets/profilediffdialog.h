// Shows what loading a profile would change (device value vs file value) before it becomes edits.
#pragma once

#include "profile.h"

#include <QDialog>

class ProfileDiffDialog : public QDialog
{
    Q_OBJECT

public:
    ProfileDiffDialog(const QString &fileName, const QVector<profile::DiffRow> &rows,
                      const model::ParameterModel &parameters, QWidget *parent = nullptr);
};
