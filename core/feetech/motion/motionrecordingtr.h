// The translation context of the motion recordings' messages, shared by the motion library's files.
#pragma once

#include <QCoreApplication>

struct MotionRecordingTr
{
    Q_DECLARE_TR_FUNCTIONS(MotionRecording)
};
