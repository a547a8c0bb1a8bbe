// Frame log of the simulator.
#include "simlog.h"

#include "hex.h"

#include <QCoreApplication>

namespace sim {

bool SimLog::open(const QString &path, QString *error)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        if (error)
            *error = QCoreApplication::translate("SimLog", "cannot write the log %1: %2")
                         .arg(path, m_file.errorString());
        return false;
    }
    return true;
}

void SimLog::write(qint64 timeUs, const char *direction, const QByteArray &bytes,
                   const QString &note)
{
    if (!m_file.isOpen())
        return;
    QByteArray line = QByteArray::number(double(timeUs) / 1e6, 'f', 6);
    line += ' ';
    line += direction;
    line += ' ';
    line += util::toHex(bytes).toLatin1();
    if (!note.isEmpty())
        line += "  # " + note.toUtf8();
    line += '\n';
    m_file.write(line);
    m_file.flush();
}

} // namespace sim
