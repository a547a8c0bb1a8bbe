// servoctl's argument handling, shared by its commands: options, usage errors, typed values.
#pragma once

#include <QCoreApplication>
#include <QMap>
#include <QSet>
#include <QStringList>
#include <QVector>

namespace cli {

// Translation context of every servoctl message.
struct ServoctlTr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

// A usage error: the message is printed as one line and servoctl exits 2.
struct UsageError
{
    QString message;
};

// Options and positional arguments of one invocation. Options may stand anywhere.
class Arguments
{
public:
    Arguments(const QStringList &raw, const QSet<QString> &valueOptions,
              const QSet<QString> &flagOptions)
    {
        for (int i = 0; i < raw.size(); ++i) {
            const QString &token = raw.at(i);
            if (!token.startsWith(QLatin1String("--")) || token == QLatin1String("--")) {
                m_positional.append(token);
                continue;
            }
            QString name = token.mid(2);
            QString value;
            bool hasValue = false;
            if (const int eq = name.indexOf(u'='); eq >= 0) {
                value = name.mid(eq + 1);
                name = name.left(eq);
                hasValue = true;
            }
            if (flagOptions.contains(name)) {
                if (hasValue)
                    throw UsageError {ServoctlTr::tr("--%1 takes no value").arg(name)};
                m_flags.insert(name);
            } else if (valueOptions.contains(name)) {
                if (!hasValue) {
                    if (i + 1 >= raw.size())
                        throw UsageError {ServoctlTr::tr("--%1 needs a value").arg(name)};
                    value = raw.at(++i);
                }
                m_values.insert(name, value);
            } else {
                throw UsageError {ServoctlTr::tr("unknown option --%1").arg(name)};
            }
        }
    }

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
// "1,2,5-7" -> 1 2 5 6 7
QVector<quint8> idList(const QString &text, int maximumId);

} // namespace cli
