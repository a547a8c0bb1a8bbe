// The translation context of servoctl's messages, shared by the command-line libraries.
#pragma once

#include <QCoreApplication>

struct ServoctlTr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};
