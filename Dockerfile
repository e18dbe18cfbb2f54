# physcheck: slim, non-root, with a health check; installs from the same lock as `make serve`.
FROM python:3.11-slim

ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_NO_CACHE_DIR=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1

WORKDIR /opt/physcheck
COPY requirements.lock ./
RUN pip install -r requirements.lock
COPY pyproject.toml README.md ./
COPY app ./app
COPY physics ./physics
COPY problems ./problems
RUN pip install --no-deps . && rm -rf build *.egg-info
# The derived bank travels with the image: a first start loads it (checked against the code's digest)
# instead of deriving the bank for a minute or more before /ready.
RUN physcheck bank build

RUN useradd --create-home --uid 10001 physcheck && mkdir /data && chown physcheck /data
USER physcheck
WORKDIR /data
ENV PHYSCHECK_DATABASE_URL=sqlite:////data/physcheck.db

EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=5s --start-period=30s \
  CMD python -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/ready', timeout=4)"
CMD ["physcheck", "serve", "--host", "0.0.0.0", "--port", "8000"]
