// The start-up probe behind bench_startup: one JSON line at the first painted frame, then quit.
#include "startupprobe.h"

#include "processmemory.h"

#include <QApplication>
#include <QEvent>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>
#include <QWidget>
#include <QWindow>

#include <cstdio>
#include <ctime>

void StartupProbe::watchIfAsked(QWidget &window)
{
    if (qEnvironmentVariableIsEmpty("SERVOBENCH_STARTUP_PROBE"))
        return;
    QWindow *handle = window.windowHandle();
    if (!handle)
        return;
    handle->installEventFilter(new StartupProbe(handle));
}

bool StartupProbe::eventFilter(QObject *watched, QEvent *event)
{
    if (!m_reported && event->type() == QEvent::Expose
        && static_cast<QWindow *>(watched)->isExposed()) {
        m_reported = true;
        // The window paints while it handles this expose; report once that is done.
        QTimer::singleShot(0, this, &StartupProbe::report);
    }
    return false;
}

void StartupProbe::report()
{
    timespec now {};
    clock_gettime(CLOCK_MONOTONIC, &now);
    QJsonObject line {
        {QStringLiteral("first_frame_monotonic_ns"),
         double(now.tv_sec) * 1e9 + double(now.tv_nsec)},
        {QStringLiteral("platform"), QGuiApplication::platformName()},
    };
    if (const auto memory = util::processMemory()) {
        line.insert(QStringLiteral("resident_mb"), memory->residentMb);
        line.insert(QStringLiteral("peak_resident_mb"), memory->peakResidentMb);
    }
    std::printf("%s\n", QJsonDocument(line).toJson(QJsonDocument::Compact).constData());
    std::fflush(stdout);
    QCoreApplication::exit(0);
}
