// The translation context of servosim's messages, shared by the simulator host's files.
#pragma once

#include <QCoreApplication>

struct ServosimTr
{
    Q_DECLARE_TR_FUNCTIONS(servosim)
};
