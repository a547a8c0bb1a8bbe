// Why a serial port would not open: no permission, another program holds it, or it is missing.
#pragma once

#include <QSerialPort>
#include <QString>

namespace seriallink {

struct PortAccess
{
    enum class Problem { None, Permission, Busy, Missing, Other };
    Problem problem = Problem::None;
    QString detail; // what the system said, for the "Other" case
    QString holder; // "servobench (pid 4242)": the program that has the port open, when known
};

// Tells a refused open apart: QSerialPort reports a port another program locked and a port
// the user may not open as the same PermissionError, so the file's access rights decide.
PortAccess classifyOpenFailure(const QString &portPath, QSerialPort::SerialPortError error,
                               const QString &systemMessage);

// Tries to open `portPath` (8N1 at 115200, closed again at once): what stands in the way.
PortAccess checkPortAccess(const QString &portPath);

// The program that has `portPath` open, as "name (pid N)", found through /proc/*/fd on Linux;
// empty where it cannot be found (other systems, or no rights to look).
QString programHoldingPort(const QString &portPath);

} // namespace seriallink
