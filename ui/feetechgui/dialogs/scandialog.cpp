// Scan options dialog: ID range, baud rates, and the quick broadcast probe.
#include "scandialog.h"

#include "modeltable.h"
#include "registertable.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

ScanDialog::ScanDialog(const feetech::ScanOptions &initial, QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Scan the bus"));
    setObjectName(QStringLiteral("scanDialog"));
    auto *layout = new QVBoxLayout(this);

    auto *ids = new QGroupBox(tr("Servo IDs"), this);
    auto *idRow = new QHBoxLayout(ids);
    m_firstId = new QSpinBox(ids);
    m_firstId->setObjectName(QStringLiteral("firstIdSpin"));
    m_lastId = new QSpinBox(ids);
    m_lastId->setObjectName(QStringLiteral("lastIdSpin"));
    for (QSpinBox *spin : {m_firstId, m_lastId})
        spin->setRange(0, feetech::kMaxServoId);
    m_firstId->setValue(initial.firstId);
    m_lastId->setValue(initial.lastId);
    idRow->addWidget(new QLabel(tr("From"), ids));
    idRow->addWidget(m_firstId);
    idRow->addWidget(new QLabel(tr("to"), ids));
    idRow->addWidget(m_lastId);
    idRow->addStretch(1);
    layout->addWidget(ids);

    auto *rates = new QGroupBox(tr("Baud rates"), this);
    auto *grid = new QGridLayout(rates);
    const QVector<qint32> all = feetech::baudRates();
    for (int i = 0; i < all.size(); ++i) {
        auto *box = new QCheckBox(tr("%L1 bps").arg(all.at(i)), rates);
        box->setObjectName(QStringLiteral("baud_%1").arg(all.at(i)));
        box->setProperty("baud", all.at(i));
        box->setChecked(initial.bauds.contains(all.at(i)));
        connect(box, &QCheckBox::toggled, this, &ScanDialog::updateEstimate);
        grid->addWidget(box, i % 4, i / 4);
        m_bauds.append(box);
    }
    auto *allButton = new QPushButton(tr("All"), rates);
    auto *noneButton = new QPushButton(tr("None"), rates);
    connect(allButton, &QPushButton::clicked, this, [this] {
        for (QCheckBox *box : std::as_const(m_bauds))
            box->setChecked(true);
    });
    connect(noneButton, &QPushButton::clicked, this, [this] {
        for (QCheckBox *box : std::as_const(m_bauds))
            box->setChecked(false);
    });
    grid->addWidget(allButton, 0, 2);
    grid->addWidget(noneButton, 1, 2);
    layout->addWidget(rates);

    m_probe = new QCheckBox(tr("Skip baud rates where nothing answers a broadcast PING"), this);
    m_probe->setObjectName(QStringLiteral("probeCheck"));
    m_probe->setChecked(initial.skipSilentRates);
    m_probe->setToolTip(tr("Every servo answers a broadcast PING. When no byte at all comes back "
                           "at a rate, no servo listens there and its IDs need not be asked one "
                           "by one. Turn off to ask every ID regardless."));
    layout->addWidget(m_probe);

    m_estimate = new QLabel(this);
    m_estimate->setObjectName(QStringLiteral("scanEstimate"));
    m_estimate->setWordWrap(true);
    m_estimate->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(m_estimate);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_scan = buttons->button(QDialogButtonBox::Ok);
    m_scan->setText(tr("Scan"));
    m_scan->setObjectName(QStringLiteral("startScanButton"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    connect(m_firstId, &QSpinBox::valueChanged, this, &ScanDialog::updateEstimate);
    connect(m_lastId, &QSpinBox::valueChanged, this, &ScanDialog::updateEstimate);
    updateEstimate();
}

feetech::ScanOptions ScanDialog::options() const
{
    feetech::ScanOptions options;
    options.firstId = std::min(m_firstId->value(), m_lastId->value());
    options.lastId = std::max(m_firstId->value(), m_lastId->value());
    options.bauds.clear();
    for (const QCheckBox *box : m_bauds) {
        if (box->isChecked())
            options.bauds.append(box->property("baud").toInt());
    }
    options.skipSilentRates = m_probe->isChecked();
    return options;
}

void ScanDialog::updateEstimate()
{
    const feetech::ScanOptions chosen = options();
    const int ids = chosen.lastId - chosen.firstId + 1;
    m_scan->setEnabled(!chosen.bauds.isEmpty());
    if (chosen.bauds.isEmpty()) {
        m_estimate->setText(tr("Choose at least one baud rate."));
        return;
    }
    m_estimate->setText(tr("%n ID(s) at %1 baud rate(s). Missing IDs cost a few milliseconds "
                           "each: the wait adapts to how fast the servos answer.",
                           nullptr, ids)
                            .arg(chosen.bauds.size()));
}
