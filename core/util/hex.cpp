// Hex text <-> bytes conversions shared by the CLI, the packet log and the tests.
#include "hex.h"

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
    out.reserve(text.size() / 2);
    // Token by token (views into the text, nothing copied), so that "0x" prefixes and
    // odd-length tokens can be reported.
    const auto take = [&](QStringView token) -> bool {
        if (token.startsWith(u"0x", Qt::CaseInsensitive))
            token = token.mid(2);
        if (token.isEmpty())
            return true;
        if (token.size() % 2 != 0) {
            if (error)
                *error = QCoreApplication::translate("util", "odd number of hex digits in \"%1\"")
                             .arg(token);
            return false;
        }
        for (qsizetype i = 0; i < token.size(); i += 2) {
            const int hi = hexDigit(token.at(i));
            const int lo = hexDigit(token.at(i + 1));
            if (hi < 0 || lo < 0) {
                if (error)
                    *error =
                        QCoreApplication::translate("util", "\"%1\" is not hexadecimal").arg(token);
                return false;
            }
            out.append(char(hi * 16 + lo));
        }
        return true;
    };
    const QStringView all(text);
    qsizetype start = 0;
    for (qsizetype i = 0; i <= all.size(); ++i) {
        if (i < all.size() && !isSeparator(all.at(i)))
            continue;
        if (!take(all.sliced(start, i - start)))
            return std::nullopt;
        start = i + 1;
    }
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
