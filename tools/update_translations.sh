#!/usr/bin/env bash
# Refreshes the Qt Linguist files translations/resect_studio_{de,fr}.ts from the tr() and
# QCoreApplication::translate() strings of widgets/ and app/studio/ (the studio's user
# interface; the CLI is not translated). New strings arrive as type="unfinished", strings
# gone from the sources are dropped. Translate the new ones (Qt Linguist, or by hand in the
# XML), then build: test_language fails while any message is unfinished or empty.
#
#     tools/update_translations.sh            both languages
#     LUPDATE=/path/to/lupdate tools/update_translations.sh
set -euo pipefail
cd "$(dirname "$0")/.."

LUPDATE=${LUPDATE:-/usr/lib/qt6/bin/lupdate}
if [ ! -x "$LUPDATE" ]; then
  echo "update_translations: $LUPDATE not found (Debian: qt6-l10n-tools)" >&2
  exit 2
fi

for lang in de fr; do
  "$LUPDATE" -I . -no-obsolete -locations relative -source-language en -target-language "$lang" \
    widgets app/studio -ts "translations/resect_studio_${lang}.ts"
done
