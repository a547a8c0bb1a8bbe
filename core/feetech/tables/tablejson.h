// What the register and model tables' loaders share: the first problem found, the document's
// root, the built-in files.
#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <optional>
#include <utility>

namespace feetech {

// Collects the first problem found in a table file; the loaders stop at it.
class TableProblems
{
public:
    explicit TableProblems(QString source)
        : m_source(std::move(source))
    { }
    bool fail(const QString &what)
    {
        if (m_message.isEmpty())
            m_message = m_source + QStringLiteral(": ") + what;
        return false;
    }
    bool ok() const { return m_message.isEmpty(); }
    const QString &message() const { return m_message; }

private:
    QString m_source;
    QString m_message;
};

// The root object of a table file: JSON, an object, "format" 1. Nothing, and the problem, else.
std::optional<QJsonObject> parseTableObject(const QByteArray &json, TableProblems &problems);
// A table file built into the program; one missing is a broken build, and fatal.
QByteArray readBuiltInTable(const QString &path);

} // namespace feetech
