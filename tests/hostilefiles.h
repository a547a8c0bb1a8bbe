// Test helper: the ways a file can be bad, made from one good file: each written into a folder
// for the readers to refuse.
#pragma once

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QString>
#include <QVector>

namespace testsupport {

struct HostileFile
{
    QString kind; // "truncated", "NaN", ...
    QString path;
};

inline constexpr qint64 kHugeFileBytes = 100 * 1024 * 1024;

// `good` with its first value that is a number (after a key) replaced by `replacement`.
inline QByteArray withFirstNumber(const QByteArray &good, const QByteArray &replacement)
{
    static const QRegularExpression number(QStringLiteral(":\\s*(-?\\d+(\\.\\d+)?)"));
    const QString text = QString::fromUtf8(good);
    const QRegularExpressionMatch match = number.match(text);
    if (!match.hasMatch())
        return good + replacement; // no number: the replacement spoils the end instead
    QString spoiled = text;
    spoiled.replace(match.capturedStart(1), match.capturedLength(1),
                    QString::fromUtf8(replacement));
    return spoiled.toUtf8();
}

// Writes each bad variant of `good` as `folder`/kind-`name`. The 100 MB one is sparse: it costs
// no disk, and a reader that read it whole would still hold 100 MB.
inline QVector<HostileFile> writeHostileFiles(const QString &folder, const QString &name,
                                              const QByteArray &good)
{
    QByteArray garbled = good;
    for (int i = 3; i < garbled.size(); i += 7)
        garbled[i] = char(garbled.at(i) ^ 0x5A);
    const int depth = 100000;
    const QByteArray nested =
        "{\"format\": " + QByteArray(depth, '[') + QByteArray(depth, ']') + "}";
    const QVector<std::pair<QString, QByteArray>> variants = {
        {QStringLiteral("empty"), QByteArray()},
        {QStringLiteral("truncated"), good.left(good.size() / 2)},
        {QStringLiteral("garbled"), garbled},
        {QStringLiteral("binary"), QByteArray("\x00\xff\xfe\x01\x89PNG\r\n", 11)},
        {QStringLiteral("wrong type"), "[" + good + "]"},
        {QStringLiteral("NaN"), withFirstNumber(good, "NaN")},
        {QStringLiteral("infinite"), withFirstNumber(good, "1e400")},
        {QStringLiteral("huge"), withFirstNumber(good, "123456789012345678901234567890")},
        {QStringLiteral("text for a number"), withFirstNumber(good, "\"twelve\"")},
        {QStringLiteral("deeply nested"), nested},
    };
    QVector<HostileFile> files;
    QDir().mkpath(folder);
    for (const auto &[kind, bytes] : variants) {
        const QString path = folder + u'/' + QString(kind).replace(u' ', u'-') + u'-' + name;
        QFile file(path);
        if (file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size())
            files.append({kind, path});
    }
    const QString huge = folder + QStringLiteral("/100MB-") + name;
    QFile file(huge);
    if (file.open(QIODevice::WriteOnly) && file.write(good) == good.size()
        && file.resize(kHugeFileBytes))
        files.append({QStringLiteral("100 MB"), huge});
    return files;
}

} // namespace testsupport
