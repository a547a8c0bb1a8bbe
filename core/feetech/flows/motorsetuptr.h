// The translation context of the motor set-up's messages, shared by its flows.
#pragma once

#include <QCoreApplication>

struct MotorSetupTr
{
    Q_DECLARE_TR_FUNCTIONS(MotorSetup)
};
