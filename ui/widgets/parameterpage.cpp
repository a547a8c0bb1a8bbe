// Parameter form: grouped rows bound by hand to the parameter model, and its buttons.
#include "parameterpage.h"

#include "palette.h"
#include "parametereditors.h"
#include "parametermodel.h"

#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

using model::Definition;
using model::ParameterModel;
using model::State;

namespace {

enum GridColumn {
    LabelColumn,
    DeviceColumn,
    EditorColumn,
    UnitColumn,
    StorageColumn,
    StateColumn,
    GridColumns
};

// State colours chosen to stay readable on light and dark palettes.
QColor stateColor(State state, bool dark)
{
    switch (state) {
    case State::Edited:
        return palette::toneColor(palette::Tone::Warning, dark);
    case State::Writing:
        return palette::toneColor(palette::Tone::Accent, dark);
    case State::Verified:
        return palette::toneColor(palette::Tone::Good, dark);
    case State::Mismatch:
    case State::Failed:
        return palette::toneColor(palette::Tone::Error, dark);
    case State::Unknown:
        return palette::toneColor(palette::Tone::Warning, dark);
    case State::Clean:
        break;
    }
    return {};
}

void setForeground(QWidget *widget, const QColor &color, bool bold)
{
    if (color.isValid()) {
        QPalette palette = widget->palette();
        palette.setColor(QPalette::WindowText, color);
        widget->setPalette(palette);
    } else {
        widget->setPalette(QPalette()); // back to the inherited palette
    }
    QFont font = widget->font();
    font.setBold(bold);
    widget->setFont(font);
}

} // namespace

ParameterPage::ParameterPage(model::ParameterModel *model, QWidget *parent)
    : ParameterPage(model, Options(), parent)
{ }

ParameterPage::ParameterPage(model::ParameterModel *model, const Options &options, QWidget *parent)
    : QWidget(parent)
    , m_options(options)
{
    setObjectName(options.objectName);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);

    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(options.objectName + QStringLiteral("ScrollArea"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *scrolled = new QWidget(scroll);
    auto *columns = new QHBoxLayout(scrolled);
    columns->setContentsMargins(12, 12, 12, 12);
    // A form column of reading width, not stretched across a wide window.
    m_form = new QWidget(scrolled);
    m_formLayout = new QVBoxLayout(m_form);
    m_formLayout->setContentsMargins(0, 0, 0, 0);
    m_formLayout->setSpacing(12);
    columns->addWidget(m_form, 1);
    columns->addStretch(0);
    scroll->setWidget(scrolled);
    layout->addWidget(scroll, 1);

    // The buttons stay outside the scroll area so Apply is always in reach.
    auto *line = new QFrame(this);
    line->setFrameShape(QFrame::HLine);
    line->setFrameShadow(QFrame::Sunken);
    layout->addWidget(line);
    auto *buttons = new QHBoxLayout;
    buttons->setContentsMargins(12, 8, 12, 10);
    buttons->setSpacing(8);
    layout->addLayout(buttons);

    const auto makeButton = [this](const QString &text, const char *name, const QString &tip) {
        auto *button = new QPushButton(text, this);
        button->setObjectName(QLatin1String(name));
        button->setToolTip(tip);
        button->setAutoDefault(false);
        return button;
    };
    m_loadProfile = makeButton(tr("Load profile…"), "loadProfileButton",
                               tr("Load parameter values from a profile file as edits"));
    m_saveProfile = makeButton(tr("Save profile…"), "saveProfileButton",
                               tr("Save the servo's parameter values to a profile file"));
    m_read = makeButton(tr("Read"), "readButton", tr("Read every parameter from the servo"));
    m_revert = makeButton(tr("Revert"), "revertButton",
                          tr("Drop every edit and show the servo's values again"));
    m_apply = makeButton(tr("Apply"), "applyButton",
                         tr("Write the edited parameters to the servo, then read them back "
                            "to verify"));
    QFont applyFont = m_apply->font();
    applyFont.setBold(true);
    m_apply->setFont(applyFont);

    m_busyLabel = new QLabel(this);
    m_busyLabel->setObjectName(QStringLiteral("busyLabel"));
    m_busyLabel->hide();
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("applyProgress"));
    m_progress->setMaximumWidth(220);
    m_progress->setFormat(tr("%v of %m"));
    m_progress->hide();

    buttons->addWidget(m_loadProfile);
    buttons->addWidget(m_saveProfile);
    buttons->addStretch(1);
    buttons->addWidget(m_busyLabel);
    buttons->addWidget(m_progress);
    buttons->addSpacing(12);
    buttons->addWidget(m_read);
    buttons->addWidget(m_revert);
    buttons->addWidget(m_apply);

    connect(m_read, &QPushButton::clicked, this, &ParameterPage::readRequested);
    connect(m_apply, &QPushButton::clicked, this, &ParameterPage::applyRequested);
    connect(m_revert, &QPushButton::clicked, this, &ParameterPage::revertAll);
    connect(m_saveProfile, &QPushButton::clicked, this, &ParameterPage::saveProfileRequested);
    connect(m_loadProfile, &QPushButton::clicked, this, &ParameterPage::loadProfileRequested);

    setModel(model);
}

void ParameterPage::setModel(model::ParameterModel *model)
{
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    if (m_model) {
        connect(m_model, &ParameterModel::parameterChanged, this, &ParameterPage::refreshRow);
        connect(m_model, &QAbstractItemModel::modelReset, this, &ParameterPage::rebuild);
        connect(m_model, &QObject::destroyed, this, [this] { setModel(nullptr); });
    }
    rebuild();
}

void ParameterPage::rebuild()
{
    m_rows.clear();
    m_rowIndex.clear();
    while (QLayoutItem *item = m_formLayout->takeAt(0)) {
        delete item->widget();
        delete item;
    }

    if (!m_model) {
        if (!m_options.emptyText.isEmpty()) {
            auto *empty = new QLabel(m_options.emptyText, this);
            empty->setObjectName(QStringLiteral("emptyState"));
            empty->setWordWrap(true);
            empty->setAlignment(Qt::AlignCenter);
            empty->setForegroundRole(QPalette::PlaceholderText);
            m_formLayout->addWidget(empty);
        }
        updateButtons();
        return;
    }
    auto *intro = new QLabel(m_options.intro.isEmpty()
                                 ? tr("<b>Device</b> is what the servo reports. Edits are written "
                                      "only when you press <b>Apply</b>, then read back and "
                                      "verified.")
                                 : m_options.intro,
                             m_form);
    intro->setObjectName(QStringLiteral("pageIntro"));
    intro->setWordWrap(true);
    intro->setForegroundRole(QPalette::PlaceholderText);
    m_formLayout->addWidget(intro);

    // Groups in the order the shown definitions first name them.
    const QVector<Definition> &definitions = m_model->definitions();
    const auto shown = [this](const Definition &definition) {
        return m_options.keys.isEmpty() || m_options.keys.contains(definition.key);
    };
    QStringList groups;
    for (const Definition &definition : definitions) {
        if (shown(definition) && !groups.contains(definition.group))
            groups.append(definition.group);
    }

    // Two columns of groups, each group going to the shorter one, so the whole form fits a
    // laptop screen without scrolling.
    auto *groupArea = new QWidget(m_form);
    auto *groupColumns = new QHBoxLayout(groupArea);
    groupColumns->setContentsMargins(0, 0, 0, 0);
    groupColumns->setSpacing(16);
    QVBoxLayout *columnLayouts[2] = {new QVBoxLayout, new QVBoxLayout};
    int columnRows[2] = {0, 0};
    for (QVBoxLayout *column : columnLayouts) {
        column->setSpacing(12);
        // A second column that gets no groups takes no room.
        groupColumns->addLayout(column, column == columnLayouts[0] || m_options.columns > 1);
    }
    m_formLayout->addWidget(groupArea);

    QVector<QGridLayout *> grids;
    for (const QString &group : std::as_const(groups)) {
        auto *box = new QGroupBox(group, groupArea);
        box->setObjectName(QStringLiteral("group_") + group);
        auto *grid = new QGridLayout(box);
        grid->setHorizontalSpacing(12);
        grid->setVerticalSpacing(6);
        grids.append(grid);

        const auto header = [&](const QString &text, int column, Qt::Alignment alignment) {
            auto *label = new QLabel(text, box);
            label->setForegroundRole(QPalette::PlaceholderText);
            grid->addWidget(label, 0, column, alignment | Qt::AlignBottom);
        };
        header(tr("Device"), DeviceColumn, Qt::AlignRight);
        header(tr("New value"), EditorColumn, Qt::AlignLeft);
        header(tr("State"), StateColumn, Qt::AlignLeft);

        int gridRow = 1;
        for (int modelRow = 0; modelRow < definitions.size(); ++modelRow) {
            const Definition &definition = definitions.at(modelRow);
            if (definition.group != group || !shown(definition))
                continue;
            Row row;
            row.key = definition.key;
            row.modelRow = modelRow;
            row.editor = createEditor(definition);
            row.editor->setParent(box);
            row.label = new QLabel(definition.label, box);
            row.label->setBuddy(row.editor);
            row.label->setToolTip(row.editor->toolTip());
            row.device = new QLabel(box);
            row.device->setObjectName(QStringLiteral("device_") + definition.key);
            row.device->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            row.device->setTextInteractionFlags(Qt::TextSelectableByMouse);
            row.unit = new QLabel(definition.unit, box);
            if (definition.storage == model::Storage::Eeprom) {
                row.storage = new QLabel(tr("EEPROM"), box);
                row.storage->setObjectName(QStringLiteral("storage_") + definition.key);
                row.storage->setForegroundRole(QPalette::PlaceholderText);
                QFont small = row.storage->font();
                small.setPointSizeF(small.pointSizeF() * 0.85);
                row.storage->setFont(small);
                row.storage->setToolTip(tr("Kept in the servo's EEPROM: written with the lock "
                                           "opened and closed again, and kept after power-off"));
                grid->addWidget(row.storage, gridRow, StorageColumn);
            }
            row.state = new QLabel(box);
            row.state->setObjectName(QStringLiteral("state_") + definition.key);
            grid->addWidget(row.label, gridRow, LabelColumn);
            grid->addWidget(row.device, gridRow, DeviceColumn);
            grid->addWidget(row.editor, gridRow, EditorColumn);
            grid->addWidget(row.unit, gridRow, UnitColumn);
            grid->addWidget(row.state, gridRow, StateColumn);
            ++gridRow;
            m_rowIndex.insert(row.key, int(m_rows.size()));
            m_rows.append(row);
        }
        grid->setColumnStretch(GridColumns, 1);
        const int column = m_options.columns > 1 && columnRows[1] < columnRows[0] ? 1 : 0;
        columnLayouts[column]->addWidget(box);
        columnRows[column] += gridRow;
    }
    for (QVBoxLayout *column : columnLayouts)
        column->addStretch(1);
    m_formLayout->addStretch(1);

    // The same column widths in every group, so the boxes read as one table.
    const QFontMetrics metrics = fontMetrics();
    QFont bold = font();
    bold.setBold(true);
    const QFontMetrics boldMetrics(bold);
    int widths[GridColumns] = {};
    widths[DeviceColumn] = metrics.horizontalAdvance(tr("Device"));
    widths[StateColumn] = boldMetrics.horizontalAdvance(
        QStringLiteral("✓ ") + ParameterModel::stateName(State::Verified));
    for (const State state :
         {State::Edited, State::Writing, State::Mismatch, State::Failed, State::Unknown})
        widths[StateColumn] = std::max(
            widths[StateColumn],
            boldMetrics.horizontalAdvance(QStringLiteral("✗ ") + ParameterModel::stateName(state)));
    for (const Row &row : std::as_const(m_rows)) {
        const Definition &definition = definitions.at(row.modelRow);
        widths[LabelColumn] = std::max(widths[LabelColumn], row.label->sizeHint().width());
        widths[EditorColumn] = std::max(widths[EditorColumn], row.editor->sizeHint().width());
        widths[UnitColumn] = std::max(widths[UnitColumn], row.unit->sizeHint().width());
        for (const qint64 raw : {definition.minimum, definition.maximum}) {
            QString shown = parametereditors::userText(definition, raw);
            if (!definition.unit.isEmpty())
                shown += u' ' + definition.unit;
            widths[DeviceColumn] = std::max(widths[DeviceColumn], metrics.horizontalAdvance(shown));
        }
        for (const model::Choice &choice : definition.choices)
            widths[DeviceColumn] =
                std::max(widths[DeviceColumn], metrics.horizontalAdvance(choice.label));
    }
    widths[LabelColumn] += 12;
    widths[DeviceColumn] += 16;
    widths[EditorColumn] = std::max(widths[EditorColumn] + 8, 110);
    widths[UnitColumn] = std::max(widths[UnitColumn], metrics.horizontalAdvance(u'm') * 3);
    int formWidth = 0;
    for (QGridLayout *grid : std::as_const(grids)) {
        for (int column = 0; column < GridColumns; ++column)
            grid->setColumnMinimumWidth(column, widths[column]);
        formWidth = std::max(formWidth, grid->minimumSize().width());
    }
    // Room for the longest state text and its neighbours to breathe.
    m_form->setMaximumWidth(std::max(std::max(m_options.columns, 1) * formWidth + 16 + 60, 640));

    for (Row &row : m_rows)
        updateRow(row);
    updateButtons();
}

QWidget *ParameterPage::createEditor(const model::Definition &definition)
{
    const QString key = definition.key;
    QWidget *editor = parametereditors::create(
        definition, this, [this, key] { editorChanged(key); },
        [this, key] { editorFinished(key); });
    editor->installEventFilter(this); // see eventFilter(): the wheel scrolls the page
    return editor;
}
bool ParameterPage::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Wheel) {
        auto *widget = qobject_cast<QWidget *>(watched);
        if (widget && !widget->hasFocus()) {
            // Ignored and filtered: the wheel goes on to the scroll area instead.
            event->ignore();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ParameterPage::editorChanged(const QString &key)
{
    if (!m_model)
        return;
    Row *row = findRow(key);
    const Definition *definition = m_model->definition(key);
    if (!row || !definition)
        return;
    QString error;
    if (parametereditors::isTypedInto(row->editor))
        row->typing = true;
    m_committing = key; // the editor is the source: the model's echo must not rewrite it
    const bool accepted = parametereditors::commit(row->editor, *m_model, key, &error);
    m_committing.clear();
    if (!accepted) {
        // The editors' ranges come from the definitions, so this is rare; say why in place.
        setForeground(row->state, stateColor(State::Failed, palette::isDark(palette())), true);
        row->state->setText(tr("Refused"));
        row->state->setToolTip(error);
    }
}

void ParameterPage::editorFinished(const QString &key)
{
    Row *row = findRow(key);
    if (!row || !row->typing)
        return;
    row->typing = false;
    // The device value may have moved while the user typed; what they see when they leave the
    // field is what they asked for, so it becomes the edit (or no edit) now.
    if (!m_busy && row->editor->isEnabled())
        editorChanged(key);
    row->typing = false;
    updateRow(*row);
}

void ParameterPage::refreshRow(const QString &key)
{
    if (Row *row = findRow(key))
        updateRow(*row);
    updateButtons();
}

void ParameterPage::updateRow(Row &row)
{
    if (!m_model)
        return;
    const Definition *definition = m_model->definition(row.key);
    if (!definition)
        return;
    const std::optional<qint64> device = m_model->deviceValue(row.key);
    const std::optional<qint64> pending = m_model->pendingValue(row.key);
    const State state = m_model->state(row.key);

    row.device->setText(
        device
            ? m_model->data(m_model->index(row.modelRow, ParameterModel::DeviceColumn)).toString()
            : tr("—"));
    row.device->setToolTip(device ? QString() : tr("Not read from the servo yet"));

    QString stateText = ParameterModel::stateName(state);
    QString stateTip;
    switch (state) {
    case State::Clean:
        break;
    case State::Edited:
        stateTip = tr("Changed here; written to the servo when you press Apply");
        break;
    case State::Writing:
        stateText += QStringLiteral("…");
        stateTip = tr("Being written to the servo");
        break;
    case State::Verified:
        stateText = QStringLiteral("✓ ") + stateText;
        stateTip = tr("Written and read back with the same value");
        break;
    case State::Mismatch:
        stateText = QStringLiteral("✗ ") + stateText;
        stateTip = tr("The value read back differs from the value written");
        break;
    case State::Failed:
        stateText = QStringLiteral("✗ ") + stateText;
        stateTip = tr("The write did not take effect; the edit is kept so you can try again");
        break;
    case State::Unknown:
        stateText = QStringLiteral("? ") + stateText;
        stateTip = tr("The write went out but no answer confirmed it, so whether the servo took "
                      "it is not known; the next read settles it, and the edit is kept");
        break;
    }
    row.state->setText(stateText);
    row.state->setToolTip(stateTip);
    setForeground(row.state, stateColor(state, palette::isDark(palette())),
                  state == State::Edited || state == State::Mismatch || state == State::Failed
                      || state == State::Unknown);

    const bool readable = device.has_value() || definition->access == model::Access::WriteOnly;
    const bool enabled = readable && !m_busy && definition->access != model::Access::ReadOnly;
    row.editor->setEnabled(enabled);
    parametereditors::setHighlighted(row.editor, pending.has_value());

    // Never under the user's fingers: not while they type in it, not while it sends its value.
    if (m_committing == row.key || (row.typing && row.editor->hasFocus()))
        return;
    row.typing = false;
    if (pending)
        showValue(row, *pending);
    else if (device)
        showValue(row, *device);
    else
        showUnread(row);
}

void ParameterPage::showUnread(Row &row)
{
    parametereditors::showUnread(row.editor);
}
void ParameterPage::showValue(Row &row, qint64 raw)
{
    if (const Definition *definition = m_model ? m_model->definition(row.key) : nullptr)
        parametereditors::showValue(row.editor, *definition, raw);
}
void ParameterPage::updateButtons()
{
    const bool present = m_model != nullptr;
    const bool edits = present && m_model->hasEdits();
    m_read->setEnabled(present && m_linkReady && !m_busy);
    m_apply->setEnabled(present && m_linkReady && edits && !m_busy);
    m_revert->setEnabled(edits && !m_busy);
    m_saveProfile->setEnabled(present && !m_busy);
    m_loadProfile->setEnabled(present && !m_busy);
}

void ParameterPage::revertAll()
{
    // An explicit Revert wins over a half-typed value.
    for (Row &row : m_rows)
        row.typing = false;
    if (m_model)
        m_model->revertAll();
}

void ParameterPage::setLinkReady(bool ready)
{
    m_linkReady = ready;
    updateButtons();
}

void ParameterPage::setBusy(bool busy, const QString &what)
{
    m_busy = busy;
    m_busyLabel->setText(what);
    m_busyLabel->setVisible(busy && !what.isEmpty());
    m_progress->setVisible(busy);
    m_progress->setRange(0, 0); // indeterminate until setProgress() says how far
    m_progress->setValue(0);
    for (Row &row : m_rows)
        updateRow(row);
    updateButtons();
}

void ParameterPage::setProgress(int done, int total)
{
    m_progress->setRange(0, std::max(total, 0));
    m_progress->setValue(std::clamp(done, 0, std::max(total, 0)));
}

QWidget *ParameterPage::editor(const QString &key) const
{
    const Row *row = findRow(key);
    return row ? row->editor : nullptr;
}

QLabel *ParameterPage::deviceLabel(const QString &key) const
{
    const Row *row = findRow(key);
    return row ? row->device : nullptr;
}

QLabel *ParameterPage::stateLabel(const QString &key) const
{
    const Row *row = findRow(key);
    return row ? row->state : nullptr;
}

ParameterPage::Row *ParameterPage::findRow(const QString &key)
{
    const int index = m_rowIndex.value(key, -1);
    return index < 0 ? nullptr : &m_rows[index];
}

const ParameterPage::Row *ParameterPage::findRow(const QString &key) const
{
    const int index = m_rowIndex.value(key, -1);
    return index < 0 ? nullptr : &m_rows.at(index);
}
