// servoctl's argument handling, shared by its commands: options, usage errors, typed values.
#pragma once

#include <QCoreApplication>
#include <QMap>
#include <QSet>
#include <QStringList>
#include <QVector>

#include <optional>

namespace cli {

// A usage error: the message is printed as one line and servoctl exits 2.
struct UsageError
{
    QString message;
};

// Options and positional arguments of one invocation. Options may stand anywhere.
class Arguments
{
public:
    // Throws UsageError for an unknown option or a missing value.
    Arguments(const QStringList &raw, const QSet<QString> &valueOptions,
              const QSet<QString> &flagOptions);

    const QStringList &positional() const { return m_positional; }
    bool flag(const QString &name) const { return m_flags.contains(name); }
    bool has(const QString &name) const { return m_values.contains(name); }
    QString value(const QString &name) const { return m_values.value(name); }
    QStringList valueNames() const { return m_values.keys(); }

private:
    QStringList m_positional;
    QSet<QString> m_flags;
    QMap<QString, QString> m_values;
};

qint64 integerOption(const Arguments &args, const QString &name, qint64 minimum, qint64 maximum);
QByteArray hexOption(const Arguments &args, const QString &name);
// --duration S: seconds above 0, or nothing when the option is absent.
std::optional<double> durationOption(const Arguments &args);
// "1,2,5-7" -> 1 2 5 6 7
QVector<quint8> idList(const QString &text, int maximumId);

} // namespace cli
