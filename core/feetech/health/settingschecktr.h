// The translation context of the settings check's messages, shared by its two files.
#pragma once

#include <QCoreApplication>

struct SettingsCheckTr
{
    Q_DECLARE_TR_FUNCTIONS(SettingsCheck)
};
