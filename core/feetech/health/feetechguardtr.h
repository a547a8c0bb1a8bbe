// The translation context of the guard's messages, shared by the health library's guard files.
#pragma once

#include <QCoreApplication>

struct FeetechGuardTr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechGuard)
};
