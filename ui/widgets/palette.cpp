// Light and dark variants of the colours the pages share.
#include "palette.h"

#include <QGuiApplication>
#include <QLabel>

namespace palette {

namespace {
// Below this lightness a background is dark enough to need light text.
constexpr int kDarkLightness = 128;
} // namespace

bool isDark(const QPalette &palette, QPalette::ColorRole role)
{
    return palette.color(role).lightness() < kDarkLightness;
}

bool isDark()
{
    return isDark(QGuiApplication::palette());
}

QColor toneColor(Tone tone, bool dark)
{
    switch (tone) {
    case Tone::Error:
        return dark ? QColor(255, 120, 110) : QColor(190, 30, 30);
    case Tone::Warning:
        return dark ? QColor(255, 196, 84) : QColor(168, 98, 0);
    case Tone::Good:
        return dark ? QColor(110, 210, 120) : QColor(30, 120, 45);
    case Tone::Accent:
        return dark ? QColor(120, 170, 255) : QColor(25, 90, 190);
    }
    return {};
}

void showInTone(QLabel *label, const QString &text, Tone tone)
{
    // The window's palette, not the label's: the label's own text colour is the last tone set.
    const QPalette &window = label->window()->palette();
    QPalette colours = label->palette();
    colours.setColor(QPalette::WindowText,
                     tone == Tone::Accent ? window.color(QPalette::WindowText)
                                          : toneColor(tone, window));
    label->setPalette(colours);
    label->setText(text);
}

} // namespace palette
