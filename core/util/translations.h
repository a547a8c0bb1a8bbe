// Loading ServoBench's translations (and Qt's own) for the language the user or the system asks.
#pragma once

#include <QLocale>
#include <QString>
#include <QStringList>

namespace util {

// The languages ServoBench is translated into besides English, by locale name: "de", "zh_CN".
QStringList translatedLanguages();

// The name of a language in that language ("Deutsch", "简体中文"; "English" for "en").
QString nativeLanguageName(const QString &language);

// Installs the translations for `language` (a locale name such as "de" or "zh_CN"; empty: the
// system's) into the running application: ServoBench's own and, where the system has them, Qt's
// (standard buttons and dialogs). English, or a language without a translation, installs none.
// Returns the locale whose translation was installed, or English.
QLocale installTranslations(const QString &language = {});

} // namespace util
