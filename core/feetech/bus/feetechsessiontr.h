// The translation context of the Feetech session's messages, which several libraries share.
#pragma once

#include <QCoreApplication>

struct FeetechSessionTr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};
