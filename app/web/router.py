"""The front door: `/` tells a visitor what they can do here."""

from __future__ import annotations

from fastapi import APIRouter, Request
from fastapi.responses import HTMLResponse

from app.web import course_pages, solution_page
from app.web.layout import page

router = APIRouter(tags=["pages"])
router.include_router(solution_page.router)
router.include_router(course_pages.router)


@router.get("/", include_in_schema=False)
async def home(request: Request) -> HTMLResponse:
    return page(request, "home.html", {"title": "Physics homework, checked"})
