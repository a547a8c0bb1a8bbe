// Port access diagnosis: permission or lock, and which program holds a busy port (Linux /proc).
#include "portaccess.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace {

struct PortAccessTr
{
    Q_DECLARE_TR_FUNCTIONS(PortAccess)
};

} // namespace

namespace seriallink {

namespace {

bool userMayOpen(const QString &portPath)
{
#ifdef Q_OS_UNIX
    return ::access(QFile::encodeName(portPath).constData(), R_OK | W_OK) == 0;
#else
    Q_UNUSED(portPath);
    return true; // elsewhere a refused open means another program has the port
#endif
}

} // namespace

PortAccess classifyOpenFailure(const QString &portPath, QSerialPort::SerialPortError error,
                               const QString &systemMessage)
{
    PortAccess access;
    access.detail = systemMessage;
    switch (error) {
    case QSerialPort::NoError:
        return access;
    case QSerialPort::DeviceNotFoundError:
        access.problem = PortAccess::Problem::Missing;
        return access;
    case QSerialPort::PermissionError:
    case QSerialPort::OpenError:
        if (!QFileInfo::exists(portPath)) {
            access.problem = PortAccess::Problem::Missing;
            return access;
        }
        if (!userMayOpen(portPath)) {
            access.problem = PortAccess::Problem::Permission;
            return access;
        }
        access.problem = PortAccess::Problem::Busy;
        access.holder = programHoldingPort(portPath);
        return access;
    default:
        access.problem = PortAccess::Problem::Other;
        return access;
    }
}

PortAccess checkPortAccess(const QString &portPath)
{
    QSerialPort port(portPath);
    if (port.open(QIODevice::ReadWrite)) {
        port.close();
        return {};
    }
    return classifyOpenFailure(portPath, port.error(), port.errorString());
}

QString programHoldingPort(const QString &portPath)
{
#ifdef Q_OS_LINUX
    const QString device = QFileInfo(portPath).canonicalFilePath();
    if (device.isEmpty())
        return {};
    const QDir proc(QStringLiteral("/proc"));
    const QStringList processes = proc.entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    for (const QString &pid : processes) {
        bool numeric = false;
        pid.toLongLong(&numeric);
        if (!numeric)
            continue;
        // Processes of other users are unreadable without rights: they are passed over.
        const QDir fds(proc.filePath(pid + QStringLiteral("/fd")));
        const QStringList entries = fds.entryList(QDir::Files | QDir::System);
        for (const QString &fd : entries) {
            if (QFileInfo(fds.filePath(fd)).symLinkTarget() != device)
                continue;
            QFile comm(proc.filePath(pid + QStringLiteral("/comm")));
            QString name;
            if (comm.open(QIODevice::ReadOnly))
                name = QString::fromLocal8Bit(comm.readAll()).trimmed();
            return name.isEmpty() ? PortAccessTr::tr("process %1").arg(pid)
                                  : PortAccessTr::tr("%1 (process %2)").arg(name, pid);
        }
    }
    return {};
#else
    Q_UNUSED(portPath);
    return {};
#endif
}

} // namespace seriallink
