// Hex text <-> bytes conversions shared by the CLI, the packet log and the tests.
#include "util/hex.h"

#include <QCoreApplication>

namespace util {

QString toHex(const QByteArray &bytes)
{
    // Written in place: the packet log and the decoder format every frame they show.
    static constexpr char16_t kDigits[] = u"0123456789ABCDEF";
    if (bytes.isEmpty())
        return {};
    QString text(bytes.size() * 3 - 1, Qt::Uninitialized);
    char16_t *out = reinterpret_cast<char16_t *>(text.data());
    for (qsizetype i = 0; i < bytes.size(); ++i) {
        if (i > 0)
            *out++ = u' ';
        const auto byte = quint8(bytes[i]);
        *out++ = kDigits[byte >> 4];
        *out++ = kDigits[byte & 0x0F];
    }
    return text;
}

static bool isSeparator(QChar c)
{
    return c.isSpace() || c == u',' || c == u':' || c == u'-' || c == u';';
}

static int hexDigit(QChar c)
{
    const char16_t u = c.unicode();
    if (u >= u'0' && u <= u'9')
        return u - u'0';
    if (u >= u'a' && u <= u'f')
        return u - u'a' + 10;
    if (u >= u'A' && u <= u'F')
        return u - u'A' + 10;
    return -1;
}

std::optional<QByteArray> parseHex(const QString &text, QString *error)
{
    QByteArray out;
    // Split into tokens first so that "0x" prefixes and odd-length tokens can be reported.
    QString token;
    const auto flush = [&]() -> bool {
        QString digits = token;
        token.clear();
        if (digits.startsWith(u"0x", Qt::CaseInsensitive))
            digits = digits.mid(2);
        if (digits.isEmpty())
            return true;
        if (digits.size() % 2 != 0) {
            if (error)
                *error = QCoreApplication::translate("util", "odd number of hex digits in \"%1\"")
                             .arg(digits);
            return false;
        }
        for (int i = 0; i < digits.size(); i += 2) {
            const int hi = hexDigit(digits.at(i));
            const int lo = hexDigit(digits.at(i + 1));
            if (hi < 0 || lo < 0) {
                if (error)
                    *error = QCoreApplication::translate("util", "\"%1\" is not hexadecimal")
                                 .arg(digits);
                return false;
            }
            out.append(char(hi * 16 + lo));
        }
        return true;
    };
    for (const QChar c : text) {
        if (isSeparator(c)) {
            if (!flush())
                return std::nullopt;
        } else {
            token.append(c);
        }
    }
    if (!flush())
        return std::nullopt;
    return out;
}

std::optional<QByteArray> parseHex(const QStringList &parts, QString *error)
{
    return parseHex(parts.join(u' '), error);
}

std::optional<qint64> parseInteger(const QString &text)
{
    const QString trimmed = text.trimmed();
    bool ok = false;
    qint64 value = 0;
    if (trimmed.startsWith(u"0x", Qt::CaseInsensitive))
        value = trimmed.mid(2).toLongLong(&ok, 16);
    else
        value = trimmed.toLongLong(&ok, 10);
    if (!ok)
        return std::nullopt;
    return value;
}

} // namespace util
