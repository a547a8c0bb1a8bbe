// Hex text <-> bytes, as users type frames ("AF FA 00 0A", "affa000a", "0xAF,0xFA").
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace util {

// Formats bytes as upper-case hex pairs separated by single spaces ("AF FA 00").
QString toHex(const QByteArray &bytes);

// Parses hex text: pairs may be separated by spaces, commas, colons or dashes, or run together,
// and may carry a 0x prefix. Returns nothing and sets *error when the text is not whole bytes.
std::optional<QByteArray> parseHex(const QString &text, QString *error = nullptr);
std::optional<QByteArray> parseHex(const QStringList &parts, QString *error = nullptr);

// Parses a decimal or 0x-prefixed hexadecimal integer; nothing when malformed.
std::optional<qint64> parseInteger(const QString &text);

} // namespace util
