// The translation context of the Feetech session's messages, shared by the bus, flows, health and session libraries.
#pragma once

#include <QCoreApplication>

struct FeetechSessionTr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};
