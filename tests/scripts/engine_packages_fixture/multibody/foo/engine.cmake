vssw_engine(NAME foo DISPLAY "Foo" ORDER 80
  DEBIAN libfoo-dev $(touch /tmp/x)
  HEADERS foo/)
