// One place for the colours the pages use, so that they stay readable on light and dark palettes
// alike and mean the same thing everywhere.
#pragma once

#include <QColor>
#include <QPalette>
#include <QString>

class QLabel;

namespace palette {

// What a coloured text says; each has one colour for light and one for dark palettes.
enum class Tone { Error, Warning, Good, Accent };

// Dark means light text on a dark background: `role` is the background the text is drawn on.
bool isDark(const QPalette &palette, QPalette::ColorRole role = QPalette::Window);
// The application's palette, for models that have no widget to ask.
bool isDark();

QColor toneColor(Tone tone, bool dark);
inline QColor toneColor(Tone tone, const QPalette &palette)
{
    return toneColor(tone, isDark(palette));
}

// Shows `text` in `label` in the tone's colour; Accent keeps the palette's own text colour (an
// outcome that is neither good nor bad, as the wizards report a step).
void showInTone(QLabel *label, const QString &text, Tone tone);

} // namespace palette
