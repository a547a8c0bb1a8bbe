// Small widget helpers shared by the pages, so their buttons and tables look and behave alike.
#pragma once

#include <QString>
#include <QStringList>

class QLabel;
class QPushButton;
class QTableView;
class QWidget;

namespace widgethelpers {

// A push button with an object name (for tests and style sheets) and a tool tip. It is never an
// auto-default button: Return in a spin box or line edit of the page must not press it.
QPushButton *actionButton(const QString &text, const char *name, const QString &tip,
                          QWidget *parent);

// Lets a table shrink to its header and `rows` rows (its own minimum, with room for scroll bars,
// is some 30 pixels more than one): on a 1366x768 screen the pages need the height. Call it once
// the rows' default height is set.
void shrinkToRows(QTableView *view, int rows = 1);

// A label that wraps its text, so a long sentence (or its translation) takes lines, not width.
QLabel *wrappedLabel(const QString &text, QWidget *parent);

// Steps for the user as a rich-text bullet list, each step's text escaped (the wizards' "do this,
// then this").
QString stepList(const QStringList &steps);

} // namespace widgethelpers
