// libFuzzer target: reading console layout files (LayoutDocument::parse).
// Whatever reads must write text that reads back to the same text: a layout
// the designer saves is never one it cannot open again.
#include "LayoutDocument.h"

#include <cstdio>
#include <cstdlib>

using namespace neptus::layout;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    auto document = LayoutDocument::parse(text);
    if (!document)
        return 0;
    const QString written = document->text();
    auto again = LayoutDocument::parse(written);
    if (!again) {
        std::fprintf(stderr, "fuzz_layout: own output does not read back: %s\n--\n%s\n--\n",
                     qPrintable(again.error().toString()), qPrintable(written));
        std::abort();
    }
    if (again->text() != written) {
        const QByteArray first = written.toUtf8(), second = again->text().toUtf8();
        std::fprintf(stderr, "fuzz_layout: writing is not stable\n--\n");
        std::fwrite(first.constData(), 1, static_cast<size_t>(first.size()), stderr);
        std::fprintf(stderr, "\n--\n");
        std::fwrite(second.constData(), 1, static_cast<size_t>(second.size()), stderr);
        std::fprintf(stderr, "\n--\n");
        std::abort();
    }
    // Edits keep it readable too.
    const QString id = document->addComponent(QStringLiteral("Gauge"), QStringLiteral("Neptus.Components"), {{QStringLiteral("x"), 1}});
    document->duplicate(id, 1, 1);
    if (!LayoutDocument::parse(document->text())) {
        std::fprintf(stderr, "fuzz_layout: an edit made it unreadable\n");
        std::abort();
    }
    return 0;
}
