# vssw on any machine with Docker (docs/guide/install.md, "Docker"). The first stage builds the project on Debian 12
# with scripts/setup.sh and makes its Debian package; the second installs that package with apt into a fresh
# Debian 12, which pulls in only what the package depends on (and gnuplot and pandas, which it recommends). In the
# image, `vssw` and `python3 -c "import vssw"` are the package's.
#   docker build -t vssw .
#   docker run --rm -v "$PWD/out:/out" vssw report --suite default --out /out/report
#   docker run --rm --entrypoint python3 vssw -c "import vssw; print(vssw.engines())"
FROM debian:12 AS build
COPY . /src
RUN bash /src/scripts/setup.sh build && cd /src/build && cpack -G DEB

FROM debian:12
COPY --from=build /src/build/vssw_*.deb /tmp/
RUN apt-get update \
 && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
      /tmp/vssw_*.deb gnuplot-nox python3-pandas \
 && rm -rf /var/lib/apt/lists/* /tmp/vssw_*.deb \
 && vssw --version && python3 -c "import vssw"
ENTRYPOINT ["vssw"]
CMD ["--help"]
