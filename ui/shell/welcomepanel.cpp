// The page shown while nothing is connected: the serial ports with their USB descriptions, the
// simulated servos, and how to wire each servo family.
#include "welcomepanel.h"

#include "connectionbar.h"
#include "serialportwatcher.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

enum PortColumnIndex {
    PortColumn,
    DescriptionColumn,
    ManufacturerColumn,
    SerialColumn,
    UsbIdColumn
};

QLabel *wrappedLabel(const QString &text, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setWordWrap(true);
    label->setTextFormat(Qt::RichText);
    return label;
}

} // namespace

WelcomePanel::WelcomePanel(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("welcomePanel"));
    auto *title = new QLabel(tr("<h2>Connect your servos</h2>"), this);
    auto *intro =
        wrappedLabel(tr("Choose the serial port of your USB adapter and press "
                        "<b>Connect</b> (or double-click it), or try ServoBench on "
                        "simulated servos. Nothing is sent to a servo until you connect."),
                     this);
    auto *columns = new QHBoxLayout;
    auto *left = new QVBoxLayout;
    left->addWidget(createPortsBox(), 1);
    left->addWidget(createSimulatedBox());
    columns->addLayout(left, 3);
    columns->addWidget(createWiringBox(), 2);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(title);
    layout->addWidget(intro);
    layout->addLayout(columns, 1);

    SerialPortWatcher &watcher = SerialPortWatcher::shared();
    connect(&watcher, &SerialPortWatcher::portsChanged, this, &WelcomePanel::showPorts);
    showPorts(watcher.ports());
}

QWidget *WelcomePanel::createPortsBox()
{
    auto *box = new QGroupBox(tr("Serial ports"), this);
    m_ports = new QTableWidget(0, 5, box);
    m_ports->setObjectName(QStringLiteral("welcomePorts"));
    m_ports->setHorizontalHeaderLabels(
        {tr("Port"), tr("Description"), tr("Manufacturer"), tr("Serial number"), tr("USB ID")});
    m_ports->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_ports->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_ports->setSelectionMode(QAbstractItemView::SingleSelection);
    m_ports->verticalHeader()->hide();
    // The description (the adapter's own name, "USB Single Serial") takes the room left; the
    // short columns keep their text's width, in any language.
    m_ports->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_ports->horizontalHeader()->setSectionResizeMode(DescriptionColumn, QHeaderView::Stretch);
    connect(m_ports, &QTableWidget::itemSelectionChanged, this, [this] {
        if (m_ports->selectedItems().isEmpty())
            return;
        emit portChosen(
            m_ports->item(m_ports->currentRow(), PortColumn)->data(Qt::UserRole).toString());
    });
    connect(m_ports, &QTableWidget::itemDoubleClicked, this, &WelcomePanel::connectSelected);
    m_noPorts = new QLabel(tr("No serial port found. Plug in the USB adapter: it shows up here "
                              "by itself."),
                           box);
    m_noPorts->setObjectName(QStringLiteral("noPortsLabel"));
    m_noPorts->setWordWrap(true);
    m_connect = new QPushButton(tr("Connect"), box);
    m_connect->setObjectName(QStringLiteral("welcomeConnectButton"));
    m_connect->setEnabled(false);
    connect(m_connect, &QPushButton::clicked, this, &WelcomePanel::connectSelected);

    auto *layout = new QVBoxLayout(box);
    layout->addWidget(m_ports, 1);
    layout->addWidget(m_noPorts);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(m_connect);
    layout->addLayout(buttons);
    return box;
}

QWidget *WelcomePanel::createSimulatedBox()
{
    auto *box = new QGroupBox(tr("Simulated servos"), this);
    auto *layout = new QHBoxLayout(box);
    const struct
    {
        QString text;
        QString port;
        const char *name;
    } buses[] = {
        {tr("PTK servo"), ConnectionBar::kSimulatedPtkPort, "simulatedPtkButton"},
        {tr("Feetech bus (five servos)"), ConnectionBar::kSimulatedFeetechPort,
         "simulatedFeetechButton"},
        {tr("SO-101 arm (six STS3215)"), ConnectionBar::kSimulatedArmPort, "simulatedArmButton"},
    };
    for (const auto &bus : buses) {
        auto *button = new QPushButton(bus.text, box);
        button->setObjectName(QLatin1String(bus.name));
        connect(button, &QPushButton::clicked, this,
                [this, port = bus.port] { emit connectRequested(port); });
        layout->addWidget(button);
    }
    layout->addStretch();
    return box;
}

QWidget *WelcomePanel::createWiringBox()
{
    auto *box = new QGroupBox(tr("Wiring"), this);
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(wrappedLabel(
        tr("<b>PTK RC servos</b> (one signal wire, 115200 baud): a 3.3 V or 5 V USB-serial "
           "adapter with a 470 Ω resistor from TX to RX. The servo's signal wire goes to RX, "
           "its ground to the adapter's ground; power the servo from its own supply. The "
           "adapter hears its own bytes, and ServoBench expects that."),
        box));
    layout->addWidget(wrappedLabel(
        tr("<b>Feetech serial-bus servos</b>: Feetech's URT-1 / FE-URT board, or any "
           "half-duplex TTL adapter (SCS, STS, HLS) or RS485 adapter (SMS). Chain the servos "
           "with their 3-wire cables; power them from the board's supply (7.4 V or 12 V as "
           "the servos ask), never from USB. New servos all answer at ID 1 and 1 Mbps: set "
           "them up one at a time (Robot > Set up motors)."),
        box));
    layout->addWidget(wrappedLabel(
        tr("Nothing answers? Leave Protocol on <b>Auto</b> and connect: ServoBench finds the "
           "family and rate, and the Doctor says what is wrong."),
        box));
    layout->addStretch();
    return box;
}

void WelcomePanel::refreshPorts()
{
    SerialPortWatcher::shared().rescan();
    showPorts(SerialPortWatcher::shared().ports());
}

void WelcomePanel::showPorts(const QVector<SerialPort> &ports)
{
    // Rebuilt only when the list changed, so the view neither flickers nor scrolls.
    if (ports == m_listed && m_ports->rowCount() == ports.size())
        return;
    m_listed = ports;
    {
        const QSignalBlocker quiet(m_ports);
        m_ports->setRowCount(0);
        for (const SerialPort &system : ports) {
            const int row = m_ports->rowCount();
            m_ports->insertRow(row);
            auto *port = new QTableWidgetItem(system.name);
            port->setData(Qt::UserRole, system.path);
            port->setToolTip(system.path);
            m_ports->setItem(row, PortColumn, port);
            m_ports->setItem(row, DescriptionColumn, new QTableWidgetItem(system.description));
            m_ports->setItem(row, ManufacturerColumn, new QTableWidgetItem(system.manufacturer));
            m_ports->setItem(row, SerialColumn, new QTableWidgetItem(system.serialNumber));
            m_ports->setItem(row, UsbIdColumn, new QTableWidgetItem(system.usbId()));
        }
    }
    m_noPorts->setVisible(ports.isEmpty());
    selectChosenRow();
}

void WelcomePanel::showChosenPort(const QString &port)
{
    m_chosen = port;
    selectChosenRow();
    m_connect->setEnabled(!port.isEmpty());
    m_connect->setToolTip(port.isEmpty() ? tr("Choose a serial port first") : QString());
}

void WelcomePanel::selectChosenRow()
{
    const QSignalBlocker quiet(m_ports);
    m_ports->clearSelection();
    for (int row = 0; row < m_ports->rowCount(); ++row) {
        if (m_ports->item(row, PortColumn)->data(Qt::UserRole).toString() == m_chosen)
            m_ports->selectRow(row);
    }
    // The view paints the selection it was not told of while its signals were blocked.
    m_ports->viewport()->update();
}

void WelcomePanel::connectSelected()
{
    if (!m_chosen.isEmpty())
        emit connectRequested(m_chosen);
}
