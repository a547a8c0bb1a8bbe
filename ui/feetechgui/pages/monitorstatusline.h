// The Monitor page's status line: one line of selectable text that changes several times a
// second (the stream's rates), measured by its font rather than by laying the text out again.
#pragma once

#include <QLabel>

#include <optional>

class MonitorStatusLine : public QLabel
{
    Q_OBJECT

public:
    explicit MonitorStatusLine(QWidget *parent = nullptr);

    // A selectable QLabel measures its text by laying out a text document, several times for
    // each new text; one line of plain text measures the same by its font's advance plus what
    // QLabel adds around it.
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void changeEvent(QEvent *event) override;

private:
    // What QLabel's own measure adds to the text's advance (its margins), and its height: taken
    // from QLabel once, and again when the font or style changes.
    mutable std::optional<QSize> m_around;
};
