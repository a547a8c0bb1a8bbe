// Loading ServoBench's translations (and Qt's own) for the language the user or the system asks.
#include "translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

namespace util {

QStringList translatedLanguages()
{
    return {QStringLiteral("de"), QStringLiteral("zh_CN")};
}

QString nativeLanguageName(const QString &language)
{
    if (language == QLatin1String("zh_CN"))
        return QStringLiteral("简体中文");
    const QLocale locale(language);
    if (locale.language() == QLocale::English || locale.language() == QLocale::C)
        return QStringLiteral("English");
    QString name = locale.nativeLanguageName();
    if (!name.isEmpty())
        name[0] = name.at(0).toUpper();
    return name;
}

QLocale installTranslations(const QString &language)
{
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    auto *own = new QTranslator(QCoreApplication::instance());
    // The compiled translations are resources of core (:/i18n/servobench_<locale>.qm); load()
    // tries the locale's UI languages in order ("de-AT" finds servobench_de.qm).
    if (!own->load(locale, QStringLiteral("servobench"), QStringLiteral("_"),
                   QStringLiteral(":/i18n"))) {
        delete own;
        return QLocale(QLocale::English);
    }
    QCoreApplication::installTranslator(own);
    // Qt's own strings (Cancel, Yes, the file dialog) come from the system's Qt translations,
    // when the distribution installed them (Debian: qt6-translations-l10n).
    auto *qt = new QTranslator(QCoreApplication::instance());
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;
    return locale;
}

} // namespace util
