// The translation context of the register tables' messages, shared by the tables library's files.
#pragma once

#include <QCoreApplication>

struct RegisterTableTr
{
    Q_DECLARE_TR_FUNCTIONS(RegisterTable)
};
