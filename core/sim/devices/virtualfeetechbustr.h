// The translation context of the simulated bus's messages, shared by the devices library's files.
#pragma once

#include <QCoreApplication>

struct VirtualFeetechBusTr
{
    Q_DECLARE_TR_FUNCTIONS(VirtualFeetechBus)
};
