// The servo tree: built from the client's servos, with the "(shared!)" and error-bit warnings.
#include "servotree.h"

#include "busclient.h"
#include "jointnames.h"
#include "palette.h"

#include <QHeaderView>
#include <QSet>
#include <QStyle>
#include <QTreeWidgetItemIterator>

namespace {

enum TreeColumn { ServoColumn, ModelColumn, FamilyColumn, FirmwareColumn, TreeColumns };
constexpr int kIdRole = Qt::UserRole + 1;
constexpr int kBaudRole = Qt::UserRole + 2;

// The servo an item of the tree stands for; nothing for the port and baud rate items.
std::optional<feetech::ServoAddress> addressOf(const QTreeWidgetItem *item)
{
    const QVariant id = item->data(ServoColumn, kIdRole);
    if (!id.isValid())
        return std::nullopt;
    return feetech::ServoAddress {quint8(id.toUInt()),
                                  qint32(item->data(ServoColumn, kBaudRole).toInt())};
}

} // namespace

ServoTree::ServoTree(feetech::BusClient *client, QWidget *parent)
    : QTreeWidget(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("servoTree"));
    setColumnCount(TreeColumns);
    setHeaderLabels({tr("Servo"), tr("Model"), tr("Family"), tr("Firmware")});
    setRootIsDecorated(true);
    setUniformRowHeights(true);
    header()->setStretchLastSection(false);
    setIndentation(fontMetrics().horizontalAdvance(u'm') * 3 / 2);
    setSelectionMode(QAbstractItemView::ExtendedSelection); // the robot actions take many
    setContextMenuPolicy(Qt::CustomContextMenu);
    connect(this, &QTreeWidget::itemSelectionChanged, this, &ServoTree::onSelectionChanged);
}

void ServoTree::setPortName(const QString &name)
{
    m_portName = name;
}

void ServoTree::rebuild(const std::optional<feetech::ServoAddress> &current)
{
    const QSignalBlocker quiet(this);
    // Servos selected for the robot actions stay selected across a rebuild (one comes after
    // every operation, a batch's included).
    QSet<feetech::ServoAddress> wasSelected;
    for (const int index : selectedServos())
        wasSelected.insert(m_client->servos()->at(index).info.address());
    clear();
    if (m_client->servos()->count() == 0)
        return;
    // An arm that matches a robot template has its servos named by joint.
    const feetech::JointNames joints = feetech::JointNames::of(*m_client);
    auto *port = new QTreeWidgetItem(this, {m_portName.isEmpty() ? tr("Bus") : m_portName});
    if (!joints.isEmpty())
        port->setToolTip(ServoColumn,
                         tr("The servos are the joints of the %1")
                             .arg(feetech::robotDisplayName(joints.robot())));
    QTreeWidgetItem *baudItem = nullptr;
    qint32 baud = 0;
    QTreeWidgetItem *selected = nullptr;
    QList<QTreeWidgetItem *> alsoSelected;
    for (int i = 0; i < m_client->servos()->count(); ++i) {
        const feetech::ServoInfo &info = m_client->servos()->at(i).info;
        if (!baudItem || info.baud != baud) {
            baud = info.baud;
            baudItem = new QTreeWidgetItem(port, {feetech::baudText(baud)});
        }
        const QString family =
            info.model.family ? feetech::familyName(*info.model.family) : tr("unknown");
        const QString idText =
            info.sharedId ? tr("ID %1 (shared!)").arg(info.id) : joints.label(info.address());
        auto *item =
            new QTreeWidgetItem(baudItem, {idText, info.model.name, family, info.firmware()});
        const std::optional<quint8> status = m_client->servos()->at(i).statusByte;
        const QStringList errors = status ? feetech::statusBitNames(*status) : QStringList();
        QStringList warnings;
        if (info.sharedId)
            warnings.append(tr("Two or more servos answer at ID %1: their replies come back "
                               "garbled. Nothing is written to this ID while it is shared; "
                               "connect them one at a time and give each its own ID.")
                                .arg(info.id));
        if (!errors.isEmpty())
            warnings.append(tr("It answers with error bits: %1 (the Doctor says why).")
                                .arg(errors.join(QStringLiteral(", "))));
        if (!warnings.isEmpty()) {
            item->setIcon(ServoColumn, style()->standardIcon(QStyle::SP_MessageBoxWarning));
            item->setToolTip(ServoColumn, warnings.join(u'\n'));
            item->setForeground(ServoColumn, palette::toneColor(palette::Tone::Error, palette()));
        }
        item->setData(ServoColumn, kIdRole, info.id);
        item->setData(ServoColumn, kBaudRole, info.baud);
        item->setToolTip(ModelColumn,
                         tr("Model number %1 (major %2, minor %3)")
                             .arg(info.modelNumber())
                             .arg(info.modelMajor)
                             .arg(info.modelMinor));
        if (!info.hasTable())
            item->setToolTip(FamilyColumn,
                             tr("No register table is known for this model: its "
                                "memory is shown as raw bytes, read-only."));
        if (current == info.address())
            selected = item;
        else if (wasSelected.contains(info.address()))
            alsoSelected.append(item);
    }
    expandAll();
    for (int column = 0; column < TreeColumns; ++column)
        resizeColumnToContents(column);
    if (selected)
        setCurrentItem(selected);
    for (QTreeWidgetItem *item : std::as_const(alsoSelected))
        item->setSelected(true);
}

QVector<int> ServoTree::selectedServos() const
{
    QVector<int> indexes;
    // The iterator takes a non-const tree but only reads it.
    for (QTreeWidgetItemIterator it(const_cast<ServoTree *>(this),
                                    QTreeWidgetItemIterator::Selected);
         *it; ++it) {
        const auto servo = addressOf(*it);
        if (!servo)
            continue;
        const int index = m_client->servos()->indexOf(*servo);
        if (index >= 0)
            indexes.append(index);
    }
    return indexes;
}

void ServoTree::onSelectionChanged()
{
    // The pages show the servo clicked last (the current item) while it is selected, else the
    // first servo selected.
    const QTreeWidgetItem *item = currentItem();
    if (!item || !item->isSelected() || !addressOf(item)) {
        item = nullptr;
        for (QTreeWidgetItem *chosen : selectedItems()) {
            if (addressOf(chosen)) {
                item = chosen;
                break;
            }
        }
    }
    if (item)
        emit servoChosen(*addressOf(item));
}
