// The editor widgets of the parameter form: a combo box for choices, a spin box in raw or scaled
// units otherwise, built from a parameter's definition and read and written without signals.
#pragma once

#include <QString>
#include <QtGlobal>

#include <functional>

class QObject;
class QWidget;

namespace model {
class ParameterModel;
struct Definition;
} // namespace model

namespace parametereditors {

// A value as the user reads it: raw × scale, in as many decimals as it needs.
QString userText(const model::Definition &definition, qint64 raw);

// The editor for `definition`, named editor_<key>, with its range (and note) as tool tip.
// `changed` runs on every change the user makes, `finished` when a spin box's editing ends.
QWidget *create(const model::Definition &definition, QObject *context,
                const std::function<void()> &changed, const std::function<void()> &finished);

// A spin box, which the user types into (a combo box is chosen from).
bool isTypedInto(const QWidget *editor);
// Sends what the editor shows to the model as an edit. False and *error when the model refuses.
bool commit(QWidget *editor, model::ParameterModel &model, const QString &key, QString *error);

// Shows `raw` (a device value or an edit) without it counting as an edit.
void showValue(QWidget *editor, const model::Definition &definition, qint64 raw);
// A dash rather than a number that would look like the servo's value.
void showUnread(QWidget *editor);
// An edited value stands out from those that match the servo.
void setHighlighted(QWidget *editor, bool highlighted);

} // namespace parametereditors
